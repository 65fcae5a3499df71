// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// "Did you mean ...?" for misspelt keys and enum values.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tessella::sim {

/// Optimal-string-alignment distance (Damerau-Levenshtein with adjacent
/// transpositions counted as one edit, no substring edited twice).
std::size_t editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word`, if close enough to be a plausible typo:
/// at most 1 edit for words of up to 4 letters, else at most a third of the
/// length (rounded up). Case is ignored. Ties go to the earlier candidate.
std::optional<std::string> closestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates);

}  // namespace tessella::sim
