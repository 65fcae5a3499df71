// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Below this many items a loop runs serially: starting an OpenMP team costs
// microseconds (much more on a busy machine), more than the loop itself.

#include <cstddef>

namespace tessella::growth {

inline constexpr std::ptrdiff_t kParallelMinItems = 4096;

}  // namespace tessella::growth
