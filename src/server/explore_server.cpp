#include "server/explore_server.h"

#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <thread>

#include "quaternia/image/png_io.h"
#include "quaternia/mesh/mesh_io.h"
#include "quaternia/mesh/mesher.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/render/pixel_certificate.h"
#include "quaternia/render/render.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"
#include "quaternia/util/memory_budget.h"
#include "server/explore_connections.h"
#include "server/explore_film.h"
#include "server/explore_sessions.h"
#include "server/explore_static.h"

namespace quaternia {

struct ExploreServer::State {
    ExploreServerOptions options;
    GuardedHttpServer http;
    RenderSlots slots;
    RenderGate gate;
    RateLimiter rateLimiter;
    std::thread thread;
    int port = -1;

    explicit State(ExploreServerOptions o)
        : options(std::move(o)),
          http(options.connections),
          gate(options.concurrentRenders),
          rateLimiter(options.requestsPerSecond, options.requestBurst) {}
};

namespace {

using Request = httplib::Request;
using Response = httplib::Response;

QueryParameters queryOf(const Request& request) {
    return QueryParameters(request.params.begin(), request.params.end());
}

void answerError(Response& response, int status, const std::string& key,
                 const std::string& message) {
    response.status = status;
    response.set_content(errorJson(key, message), "application/json");
}

// Runs a route body, turning a UserError (a bad key or value) into 400 naming the key, and
// anything else into 500 without a crash.
void guarded(Response& response, const std::function<void()>& body) {
    try {
        body();
    } catch (const UserError& e) {
        answerError(response, 400, e.key(), e.what());
    } catch (const std::exception& e) {
        answerError(response, 500, "", std::string("internal error: ") + e.what());
    }
}

void answerBytes(Response& response, const std::vector<uint8_t>& bytes, const char* type) {
    response.set_content(reinterpret_cast<const char*>(bytes.data()), bytes.size(), type);
    response.set_header("Cache-Control", "no-store");
}

// A long job in the client's render slot, within the render gate. Returns false, having
// answered 204, when a newer request of the same client cancelled it first.
template <typename Job>
bool runInSlot(ExploreServer::State& state, const std::string& client, Response& response,
               Job job) {
    CancelFlag cancel = state.slots.begin(client);
    struct SlotEnd {
        RenderSlots& slots;
        const std::string& client;
        const CancelFlag& flag;
        ~SlotEnd() { slots.end(client, flag); }
    } slotEnd{state.slots, client, cancel};
    RenderGate::Pass pass(state.gate, *cancel);
    WorkOptions work;
    work.threads = state.options.renderThreads;
    work.cancel = cancel.get();
    if (!pass.entered() || !job(work)) {
        response.status = 204;  // superseded: the page has moved on
        return false;
    }
    return true;
}

// Renders `scene` in `slot` and answers its PNG, or 204 when a newer request cancelled it.
// Returns whether it answered the image.
// A render's share of the server's memory budget: each of the renders at once may take it.
MemoryBudget renderShare(const ExploreServer::State& state) {
    MemoryBudget share = state.options.memory;
    share.bytes /= uint64_t(std::max(1, state.options.concurrentRenders));
    if (share.bytes == 0 && state.options.memory.bytes != 0) share.bytes = 1;
    share.source +=
        " shared by " + std::to_string(state.options.concurrentRenders) + " renders at once";
    return share;
}

void requireImageMemory(const ExploreServer::State& state, const Scene& scene, uint64_t bytes) {
    requireMemory(bytes, renderShare(state), "render.width",
                  "render.width x render.height = " + std::to_string(scene.render.width) + " x " +
                      std::to_string(scene.render.height) + ": the image",
                  "lower render.width and render.height");
}

// A header value of one line of printable ASCII (a message may quote a formula).
std::string headerText(const std::string& text) {
    std::string out = text;
    for (char& ch : out)
        if (ch < 0x20 || ch > 0x7e) ch = '?';
    return out;
}

// With `certify`, the picture's certificate (pixel_certificate.h) is made after the render, in
// the same slot, and its undecided pixels are tinted magenta; X-Certify-Undecided gives their
// fraction. Where validateCertificate refuses the scene, the picture is answered untinted, with
// the refusal in X-Certify-Error and its key in X-Certify-Key.
bool answerRender(ExploreServer::State& state, const std::string& slot, const Scene& scene,
                  Response& response, bool certify = false) {
    if (certify) {
        try {
            validateCertificate(scene);
        } catch (const UserError& refusal) {
            certify = false;
            response.set_header("X-Certify-Error", headerText(refusal.what()));
            response.set_header("X-Certify-Key", headerText(refusal.key()));
        }
    }
    const uint64_t pixels = uint64_t(scene.render.width) * uint64_t(scene.render.height);
    requireImageMemory(
        state, scene,
        renderPngMemoryBytes(scene, false) + (certify ? pixels * (1 + 2 * sizeof(float)) : 0));
    requireFractalMemory(scene, renderShare(state));
    RenderResult result;
    PixelCertificate certificate;
    bool done = runInSlot(state, slot, response, [&](const WorkOptions& w) {
        RenderOptions options;
        static_cast<WorkOptions&>(options) = w;
        result = render(scene, options);
        if (!result.completed || !certify) return result.completed;
        certificate = certifyPixels(scene, w);
        return certificate.completed;
    });
    if (!done) return false;
    if (certify) {
        tintUndecided(result.image, certificate);
        response.set_header("X-Certify-Undecided",
                            std::to_string(certificate.counts.undecidedFraction()));
        response.set_header("X-Certify-Ms", std::to_string(certificate.seconds * 1000));
    }
    answerBytes(
        response,
        encodePng(result.image, scene.render.bitDepth, scene.render.alpha == AlphaMode::Opaque),
        "image/png");
    response.set_header("X-Render-Ms", std::to_string(result.stats.seconds * 1000));
    return true;
}

void renderRoute(ExploreServer::State& state, const Request& request, Response& response,
                 bool download) {
    guarded(response, [&] {
        QueryParameters query = queryOf(request);
        std::string client = clientIdFromQuery(query);
        Scene scene = sceneFromQuery(state.options.startScene, query, state.options.limits);
        if (download)
            checkDownloadImage(scene, state.options.limits);
        else
            checkInteractiveImage(scene, state.options.limits);
        const bool certify = certifyFromQuery(query);
        if (answerRender(state, download ? "" : client, scene, response, certify) && download)
            response.set_header("Content-Disposition", "attachment; filename=\"quaternia.png\"");
    });
}

// One frame of the film, in a slot of its own per tab so that playing and the live view do not
// cancel each other; a newer frame of the same tab cancels a stale one.
void frameRoute(ExploreServer::State& state, const Request& request, Response& response) {
    guarded(response, [&] {
        QueryParameters query = queryOf(request);
        int64_t frame = takeFrameNumber(query);
        std::string client = clientIdFromQuery(query);
        Scene film = sceneFromQuery(state.options.startScene, query, state.options.limits);
        Scene scene = filmFrame(film, frame, state.options.limits);
        answerRender(state, client.empty() ? "" : client + "-film", scene, response);
    });
}

void mandelbrotRoute(ExploreServer::State& state, const Request& request, Response& response) {
    guarded(response, [&] {
        QueryParameters query = queryOf(request);
        std::string client = clientIdFromQuery(query);
        Scene scene = sceneFromQuery(state.options.startScene, query, state.options.limits);
        int64_t pixels = int64_t{scene.render.width} * scene.render.height;
        if (pixels > state.options.limits.planePixels)
            throw UserError("render.width", "the map is limited to " +
                                                std::to_string(state.options.limits.planePixels) +
                                                " pixels");
        scene.plane.kind = PlaneKind::Mandelbrot;
        requireImageMemory(state, scene, planeMemoryBytes(scene));
        try {
            validatePlaneScene(scene);
        } catch (const UserError&) {
            // The Mandelbrot set is drawn for formulas z^d + c; for any other the map shows
            // that of z^2 + c, which still picks a c.
            scene.fractal.formula = "z^2 + c";
            response.set_header("X-Map-Formula", "z^2 + c");
        }
        PlaneImage image;
        if (!runInSlot(state, client.empty() ? "" : client + "-map", response,
                       [&](const WorkOptions& w) {
                           image = renderPlane(scene, w);
                           return image.completed;
                       }))
            return;
        answerBytes(response, encodePng(image.image, 8), "image/png");
    });
}

void meshRoute(ExploreServer::State& state, const Request& request, Response& response) {
    guarded(response, [&] {
        QueryParameters query = queryOf(request);
        Scene scene = sceneFromQuery(state.options.startScene, query, state.options.limits);
        checkMeshRequest(scene, state.options.limits);
        MeshResult mesh;
        if (!runInSlot(state, "", response, [&](const WorkOptions& w) {
                MeshOptions meshOptions{w};
                meshOptions.memory = renderShare(state);
                mesh = meshScene(scene, meshOptions);
                return mesh.completed;
            }))
            return;
        answerBytes(response, encodeMesh(mesh.mesh, MeshFormat::Stl), "model/stl");
        response.set_header("Content-Disposition", "attachment; filename=\"quaternia.stl\"");
    });
}

void addRoutes(ExploreServer::State& state) {
    httplib::Server& http = state.http;
    // The page: only the paths of the embedded map; anything else (../, %2e%2e, absolute paths)
    // finds no route and is answered 404 by the error handler.
    for (const auto& [path, file] : exploreStaticFiles()) {
        StaticFile content = file;
        http.Get(path, [content](const Request&, Response& response) {
            response.set_content(content.body.data(), content.body.size(),
                                 std::string(content.contentType).c_str());
        });
    }
    http.Get("/api/parameters", [&state](const Request&, Response& response) {
        response.set_content(parameterTableJson(state.options.startScene), "application/json");
    });
    http.Get("/api/presets", [](const Request&, Response& response) {
        response.set_content(presetsJson(), "application/json");
    });
    http.Get("/api/render", [&state](const Request& request, Response& response) {
        renderRoute(state, request, response, false);
    });
    http.Get("/api/frame", [&state](const Request& request, Response& response) {
        frameRoute(state, request, response);
    });
    http.Get("/api/film", [&state](const Request& request, Response& response) {
        guarded(response, [&] {
            Scene film =
                sceneFromQuery(state.options.startScene, queryOf(request), state.options.limits);
            response.set_content(filmJson(film), "application/json");
        });
    });
    http.Get("/api/download", [&state](const Request& request, Response& response) {
        renderRoute(state, request, response, true);
    });
    http.Get("/api/mandelbrot", [&state](const Request& request, Response& response) {
        mandelbrotRoute(state, request, response);
    });
    http.Get("/api/mesh", [&state](const Request& request, Response& response) {
        meshRoute(state, request, response);
    });
    http.Get("/api/scene", [&state](const Request& request, Response& response) {
        guarded(response, [&] {
            Scene scene =
                sceneFromQuery(state.options.startScene, queryOf(request), state.options.limits);
            if (isAnimated(scene)) validateAnimation(scene);  // what quaternia animate refuses
            response.set_content(sceneToToml(scene), "application/toml");
        });
    });
    http.Get("/api/command", [&state](const Request& request, Response& response) {
        guarded(response, [&] {
            Scene scene =
                sceneFromQuery(state.options.startScene, queryOf(request), state.options.limits);
            response.set_content(renderCommandForScene(scene) + "\n", "text/plain");
        });
    });
}

void configure(ExploreServer::State& state) {
    httplib::Server& http = state.http;
    // Per read and write; a whole request has its deadline besides (explore_connections.h),
    // and keep-alive its own wait.
    http.set_read_timeout(5, 0);
    http.set_write_timeout(10, 0);
    http.set_payload_max_length(64 * 1024);  // every route is a GET; bodies are never read
    http.set_pre_routing_handler([&state](const Request& request, Response& response) {
        // Before any body is read: HEAD is answered as GET without the body.
        if (request.method != "GET" && request.method != "HEAD") {
            answerError(response, 405, "method",
                        "method " + request.method + " is not allowed; the explorer answers GET");
            response.set_header("Allow", "GET, HEAD");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (state.rateLimiter.allow(request.remote_addr))
            return httplib::Server::HandlerResponse::Unhandled;
        answerError(response, 429, "", "too many requests; slow down");
        return httplib::Server::HandlerResponse::Handled;
    });
    http.set_error_handler([](const Request&, Response& response) {
        // Routes answer their own 400s and 429s with a body; fill in the rest.
        if (!response.body.empty()) return;
        if (response.status == 404)
            answerError(response, 404, "path", "not found");
        else
            answerError(response, response.status, "", "bad request");
    });
    http.set_exception_handler([](const Request&, Response& response, std::exception_ptr) {
        answerError(response, 500, "", "internal error");
    });
    addRoutes(state);
}

}  // namespace

ExploreServer::ExploreServer(ExploreServerOptions options)
    : state_(std::make_unique<State>(std::move(options))) {
    configure(*state_);
}

ExploreServer::~ExploreServer() {
    stop();
}

int ExploreServer::bind() {
    if (state_->port >= 0) return state_->port;
    const auto& o = state_->options;
    int port = o.port == 0 ? state_->http.bind_to_any_port(o.bind)
                           : (state_->http.bind_to_port(o.bind, o.port) ? o.port : -1);
    if (port >= 0) state_->http.widenBacklog();
    if (port < 0) {
        throw UserError("--bind", "cannot listen on " + o.bind + " port " + std::to_string(o.port) +
                                      " (in use, or not an address of this machine)");
    }
    return state_->port = port;
}

int ExploreServer::port() const {
    return state_->port;
}

ExploreConnectionStats ExploreServer::connectionStats() const {
    return state_->http.stats();
}

int ExploreServer::rendersRunning() const {
    return state_->gate.running();
}

void ExploreServer::run() {
    bind();
    state_->http.listen_after_bind();
}

void ExploreServer::start() {
    bind();
    state_->thread = std::thread([this] { state_->http.listen_after_bind(); });
    // listen_after_bind sets is_running before it accepts; wait so stop() cannot race it.
    while (!state_->http.is_running())
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void ExploreServer::stop() {
    state_->slots.cancelAll();
    state_->http.stop();
    if (state_->thread.joinable()) state_->thread.join();
}

}  // namespace quaternia
