// Writes a built-in environment (environment.builtin: "studio" or "sky", with the default
// scene's keys) as a latitude-longitude Radiance .hdr map, the file data/environments/studio.hdr
// was made with:
//   build/quaternia_environment_map studio 512 data/environments/studio.hdr
// (Environment.ShippedStudioMapIsTheBuiltin holds the shipped file to the built-in.)
#include <cstdio>
#include <exception>
#include <string>

#include "quaternia/render/environment.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/atomic_file.h"

int main(int argc, char** argv) {
    using namespace quaternia;
    if (argc != 4) {
        std::fprintf(stderr, "usage: quaternia_environment_map studio|sky WIDTH OUT.hdr\n");
        return 2;
    }
    try {
        Scene scene = defaultScene();
        setParameter(scene, "environment.builtin", std::string(argv[1]));
        const int width = std::stoi(argv[2]);
        if (width < 8 || width > 16384 || width % 2 != 0) {
            std::fprintf(stderr, "quaternia_environment_map: WIDTH must be even, 8 to 16384\n");
            return 2;
        }
        AtomicFile file(argv[3]);
        file.write(encodeRadianceHdr(builtinMap(scene.environment, width)));
        file.commit();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia_environment_map: %s\n", e.what());
        return 2;
    }
    return 0;
}
