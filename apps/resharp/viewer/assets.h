#pragma once
/// What the viewer page is made of, embedded at build time (embed_assets.cmake).

#include <string_view>

namespace resharp::viewer {

/// page.html, with the markers @TITLE@, @DATA@, @SCRIPT@ and @LICENSE@.
extern const std::string_view kTemplate;
/// viewer.js bundled with three.js by esbuild, minified.
extern const std::string_view kScript;
/// The licence text of the bundled three.js, kept in every page.
extern const std::string_view kLicense;

}  // namespace resharp::viewer
