// `quaternia explore`'s HTTP server (cpp-httplib): the embedded page, the parameter table as
// JSON, and images, scene files, CLI commands and meshes of the view a request's query names.
// Every query parameter is a scene key checked by the parameter table; a bad one is answered
// 400 with {"error": ..., "key": ...}. Connections are bounded per address and in all, and
// requests by a deadline (ExploreConnectionLimits, explore_connections.h). Library-like: it never
// prints or exits, so the tests run it in-process.
//
// Routes (GET; HEAD answers as GET without the body; any other method is 405 naming "method",
// before its body is read, and the connection closes):
//   /, /index.html, /explore.js, /explore.css    the page (exactly these paths, nothing else)
//   /api/parameters     the table, with the starting scene's values
//   /api/render         PNG of the view, at most ExploreLimits::interactivePixels; 204 when a
//                       newer request of the same `client` cancelled it
//                       (certify=true: the certificate's undecided pixels tinted magenta,
//                       X-Certify-Undecided their fraction; a scene the certificate refuses
//                       is drawn untinted, the refusal in X-Certify-Error and X-Certify-Key)
//   /api/frame          PNG of frame `frame` (from 1) of the view's film (animation.keys and
//                       [animation]): the library's sceneAtFrame, limited as /api/render;
//                       204 when a newer frame of the same `client` cancelled it
//   /api/film           the film's frame count, fps and keys as JSON (explore_film.h)
//   /api/download       PNG as an attachment, up to 4096 x 4096 (certify as /api/render)
//   /api/mandelbrot     PNG of the Mandelbrot set of the formula (z^2 + c when it has none)
//   /api/scene          the view as a scene file (TOML), with its [animation] and keys
//   /api/command        the view as a `quaternia render` command line
//   /api/mesh           binary STL of the view's set, mesh.resolution at most 256
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "quaternia/scene/scene.h"
#include "quaternia/util/memory_budget.h"
#include "server/explore_request.h"

namespace quaternia {

// Bounds on connections, against clients that open many or send slowly: a connection beyond
// the limits is refused at once (503, then closed), and a request must arrive by a deadline.
// Connections are served on total + a few threads, so admitted slow ones never take them all.
struct ExploreConnectionLimits {
    int perAddress = 16;  // connections served at once per remote address
    int total = 128;      // connections served at once in all
    // Reading one request, from its first byte to the end of its header (and of a body, which
    // no route reads: methods other than GET and HEAD are refused before it).
    double requestSeconds = 10;
    double idleSeconds = 2;  // waiting for a connection's next request (keep-alive)
    int requestsPerConnection = 100;
};

// What the limits did, counted since the server started.
struct ExploreConnectionStats {
    uint64_t refused = 0;   // connections beyond a limit, answered 503
    uint64_t timedOut = 0;  // connections closed when a request missed its deadline
};

struct ExploreServerOptions {
    std::string bind = "127.0.0.1";  // loopback unless told otherwise
    int port = 8080;                 // 0: any free port (see ExploreServer::port)
    Scene startScene;                // what the page starts from; query keys apply on top
    int renderThreads = 0;           // per render; 0 = every core
    int concurrentRenders = 2;       // renders running at once; more requests wait
    double requestsPerSecond = 100;  // per remote address, with bursts of requestBurst
    double requestBurst = 200;
    ExploreLimits limits;
    ExploreConnectionLimits connections;
    // The memory renders may take, shared by the concurrentRenders at once: a request whose
    // estimate exceeds its share is refused (400 naming render.width or mesh.resolution).
    MemoryBudget memory;  // unlimited unless set
};

class ExploreServer {
  public:
    explicit ExploreServer(ExploreServerOptions options);
    ~ExploreServer();  // stops
    ExploreServer(const ExploreServer&) = delete;
    ExploreServer& operator=(const ExploreServer&) = delete;

    // Binds the socket; throws UserError("--bind", ...) when it cannot. Returns the port.
    int bind();
    int port() const;
    ExploreConnectionStats connectionStats() const;
    // Renders (and meshes, maps) running now, within ExploreServerOptions::concurrentRenders.
    int rendersRunning() const;
    // Serves until stop() (from another thread or a signal handler's thread).
    void run();
    // bind() (if not yet) and run() on a background thread; for tests.
    void start();
    // Cancels running renders, stops serving, joins the background thread.
    void stop();

    struct State;  // defined in explore_server.cpp

  private:
    std::unique_ptr<State> state_;
};

}  // namespace quaternia
