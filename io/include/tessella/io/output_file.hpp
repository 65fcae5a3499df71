// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Checking an output file before any work: a run or a mesh that takes
// minutes should not fail at its last step because of a mistyped path.

#include <string>

namespace tessella::io {

/// Throws InputError unless a file can be written at `path`: the name is not
/// empty, the path is not a directory, and its directory exists and is
/// writable. The message starts with `label` (a flag or key naming the
/// output, e.g. "--out") and the path.
void checkOutputFile(const std::string& path, const std::string& label);

}  // namespace tessella::io
