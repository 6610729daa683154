// The explorer's page (web/index.html, explore.js, explore.css), embedded into the binary at
// build time (cmake/embed_files.cmake writes explore_static_files.cpp). The server answers only
// the request paths of this map, so no request ever reaches the file system.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace quaternia {

struct StaticFile {
    std::string_view contentType;
    std::string_view body;
};

// Request path ("/", "/explore.js", ...) to file.
const std::map<std::string, StaticFile>& exploreStaticFiles();

}  // namespace quaternia
