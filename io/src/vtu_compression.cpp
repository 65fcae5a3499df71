#include "tessella/io/vtu.hpp"

#include <algorithm>
#include <cctype>

#include "tessella/tissue/errors.hpp"

namespace tessella::io {

Compression parseCompression(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (lower == "none") return Compression::None;
  if (lower == "lz4") return Compression::LZ4;
  if (lower == "zlib") return Compression::ZLib;
  throw InputError("unknown compression '" + name + "' (expected none, lz4 or zlib)");
}

const char* compressionName(Compression c) {
  switch (c) {
    case Compression::None: return "none";
    case Compression::LZ4: return "lz4";
    case Compression::ZLib: return "zlib";
  }
  return "unknown";
}

}  // namespace tessella::io
