// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/output_section.hpp"

#include <algorithm>
#include <cctype>

namespace tessella::sim {

void declareOutputSection(Schema& s) {
  s.section("output", "The ParaView series: DIR/NAME.pvd listing DIR/NAME_000000.vtu, ... (open the "
                      ".pvd in ParaView), next to DIR/run.yaml.");
  s.key("output.directory", ValueType::String,
        "Directory of the series, relative to the working directory. `tessella run --out DIR` "
        "overrides it. A directory that already holds a run is refused unless --overwrite is given.")
      .whenAbsent("runs/<config file name without .yaml>");
  s.key("output.name", ValueType::String,
        "Series name: the .pvd and .vtu file names start with it (letters, digits, '_', '-', '.').")
      .byDefault(std::string("tissue"));
  s.key("output.every", ValueType::Int,
        "Write a snapshot every this many steps. The initial and the final states are always written.")
      .byDefault(std::int64_t{1})
      .atLeast(1);
  s.key("output.compression", ValueType::Enum,
        "Compression of the .vtu data: lz4 is fast, zlib a few percent smaller and much slower to write.")
      .oneOf(io::compressions().names())
      .byDefault(std::string("lz4"));
}

OutputSpec readOutputSection(const Config& c) {
  OutputSpec out;
  if (c.has("output.directory")) {
    out.directory = c.getString("output.directory");
    if (out.directory.empty()) throw c.errorAt("output.directory", "must not be empty");
  }
  out.name = c.getString("output.name");
  const bool plain = !out.name.empty() && out.name != "." && out.name != ".." &&
                     std::all_of(out.name.begin(), out.name.end(), [](unsigned char ch) {
                       return std::isalnum(ch) || ch == '_' || ch == '-' || ch == '.';
                     });
  if (!plain)
    throw c.errorAt("output.name", "must be a plain file name (letters, digits, '_', '-', '.'), got '" +
                                       out.name + "'");
  out.every = static_cast<std::size_t>(c.getInt("output.every"));
  out.vtu.compression = io::parseCompression(c.getString("output.compression"));
  return out;
}

}  // namespace tessella::sim
