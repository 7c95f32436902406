// tessera/version.hpp — library and file-format versions.
#pragma once

namespace tessera {
inline constexpr const char* version = "0.1.0";
inline constexpr int format_version = 1;  // "version" written in native JSON files
}  // namespace tessera
