// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Below this many items a loop runs serially: starting an OpenMP team costs
// microseconds (much more on a busy machine), more than the loop itself.

#include <cstddef>

namespace tessella::growth {

inline constexpr std::ptrdiff_t kParallelMinItems = 4096;

/// Loops over every vertex or cell deal chunks of this many items to the
/// threads in turn (`schedule(static, kInterleavedChunk)`) rather than one
/// contiguous share each: on a growing tissue the last items (the newest
/// elements, in array pages first touched in that loop) cost more, and with
/// contiguous shares they all fell to the last thread, which the others then
/// waited for.
inline constexpr int kInterleavedChunk = 4096;

}  // namespace tessella::growth
