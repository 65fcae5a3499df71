// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Small text files (run records, collections) written the way snapshots are:
// to a temporary file in the same directory, then renamed over the target.

#include <string>
#include <string_view>

namespace tessella::io {

/// Writes `text` to `path` atomically: readers see the old file or the new
/// one, and a failure (disk full, no permission) leaves no temporary file and
/// throws InputError naming `path` and the operating system's reason. With
/// `durable`, the data reach the disk (fsync) before the rename.
void writeTextFile(const std::string& path, std::string_view text, bool durable = false);

}  // namespace tessella::io
