// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Quoting file contents in error messages: a line of a user's file may be
// megabytes long or hold binary bytes, and must not flood or garble a
// terminal.

#include <cstddef>
#include <string>
#include <string_view>

namespace tessella {

/// `text` made safe to print: bytes other than printable ASCII are written
/// \xNN (tabs too; backslashes stay as they are), and text longer than
/// `max_bytes` is cut there and followed by "... (N more bytes)".
std::string excerpt(std::string_view text, std::size_t max_bytes = 80);

}  // namespace tessella
