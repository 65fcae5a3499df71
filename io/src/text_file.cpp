// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/io/text_file.hpp"

#include "atomic_file.hpp"

namespace tessella::io {

void writeTextFile(const std::string& path, std::string_view text, bool durable) {
  detail::replaceAtomically(path, [&](const std::string& tmp) { detail::writeBytes(tmp, text, path); }, durable);
}

}  // namespace tessella::io
