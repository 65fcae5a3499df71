// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/io/vtu.hpp"

#include <algorithm>
#include <cctype>

#include "tessella/tissue/errors.hpp"

namespace tessella::io {

const EnumTable<Compression>& compressions() {
  static const EnumTable<Compression> table(
      "compression", {{"none", Compression::None, "Raw binary."},
                      {"lz4", Compression::LZ4, "Fast."},
                      {"zlib", Compression::ZLib, "A few percent smaller than lz4, much slower to write."}});
  return table;
}

Compression parseCompression(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  for (const auto& e : compressions().entries())
    if (e.name == lower) return e.value;
  throw InputError("unknown compression '" + name + "' (known: " + compressions().namesText() + ")");
}

const char* compressionName(Compression c) { return compressions().name(c).c_str(); }

}  // namespace tessella::io
