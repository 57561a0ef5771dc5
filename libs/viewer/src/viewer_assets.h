// The page's build-time assets, compiled in by libs/viewer/CMakeLists.txt
// (generated source, see tools/viewer/embed_cpp.js): planar-mapper needs no
// file, network or Node.js at run time.
#pragma once

#include <string_view>

namespace pmap::viewer::assets {

/// tools/viewer/*.js with three.js, bundled by esbuild into one classic
/// (IIFE) script.
std::string_view viewerScript();

/// tools/viewer/viewer.template.html.
std::string_view pageTemplate();

}  // namespace pmap::viewer::assets
