// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Atomic replacement of a file: write everything to a temporary file in the
// same directory, then rename it over the target. rename() within one
// directory is atomic on POSIX file systems, so readers (and a run that is
// killed mid-write) see either the old complete file or the new one.

#include <functional>
#include <string>
#include <string_view>

namespace tessella::io::detail {

/// Calls write(temporary_path), then renames the temporary file to `path`.
/// If write throws, or the rename fails, the temporary file is removed and
/// the target is left untouched; rename failures throw InputError naming
/// `path`. With `durable`, the data are flushed to disk (fsync) before the
/// rename, so a power cut cannot leave an empty file under `path` either.
void replaceAtomically(const std::string& path, const std::function<void(const std::string&)>& write,
                       bool durable = false);

/// The operating system's words for an errno value ("No space left on device").
std::string osReason(int error);

/// Writes `data` to `file` (created or truncated) with POSIX calls, so that a
/// failure is an InputError naming `target` (the file the user asked for) and
/// the operating system's reason.
void writeBytes(const std::string& file, std::string_view data, const std::string& target);

}  // namespace tessella::io::detail
