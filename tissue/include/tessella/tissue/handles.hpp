// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Typed, index-based handles for the elements of a cell complex.
//
// A handle is a small index into the per-degree stores of a Tissue, never a
// pointer: it survives every edit that does not remove its element, and is
// renumbered only by Tissue::compact(). A default-constructed handle is
// invalid.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>

namespace tessella {

using Index = std::uint32_t;
inline constexpr Index kInvalidIndex = std::numeric_limits<Index>::max();

template <typename Tag>
class Handle {
 public:
  constexpr Handle() = default;
  constexpr explicit Handle(Index index) : index_(index) {}
  constexpr Index index() const { return index_; }
  constexpr bool valid() const { return index_ != kInvalidIndex; }
  constexpr explicit operator bool() const { return valid(); }
  friend constexpr auto operator<=>(Handle, Handle) = default;

 private:
  Index index_ = kInvalidIndex;
};

// Topological handles: the degree is part of the type.
struct VertexTag {};
struct EdgeTag {};
struct FaceTag {};    // degree 2: a polygon (a 2D cell or a 3D wall)
struct VolumeTag {};  // degree 3: a polyhedron (a 3D cell)
// Role handles: a cell is the top-degree element (face in 2D, volume in 3D),
// a wall the element of degree D-1 (edge in 2D, face in 3D). Code written
// against CellId/WallId runs unchanged on 2D, surface and 3D tissues.
struct CellTag {};
struct WallTag {};

using VertexId = Handle<VertexTag>;
using EdgeId = Handle<EdgeTag>;
using FaceId = Handle<FaceTag>;
using VolumeId = Handle<VolumeTag>;
using CellId = Handle<CellTag>;
using WallId = Handle<WallTag>;

/// Converts between handle types that share an index (e.g. FaceId -> CellId
/// in a 2D tissue). The caller asserts the degrees match.
template <typename To, typename From>
constexpr To handle_cast(From h) {
  return To(h.index());
}

/// A handle with an orientation: an edge traversed from its second vertex to
/// its first, or a face whose loop normal points into (not out of) a volume.
template <typename H>
class Oriented {
 public:
  constexpr Oriented() = default;
  constexpr Oriented(H h, bool reversed = false)  // NOLINT: implicit by design
      : packed_(h.valid() ? (h.index() << 1) | (reversed ? 1u : 0u) : kInvalidIndex) {}
  constexpr H handle() const { return packed_ == kInvalidIndex ? H() : H(packed_ >> 1); }
  constexpr bool reversed() const { return packed_ & 1u; }
  constexpr int sign() const { return reversed() ? -1 : 1; }
  constexpr Oriented flipped() const { return Oriented(handle(), !reversed()); }
  friend constexpr bool operator==(Oriented, Oriented) = default;

 private:
  Index packed_ = kInvalidIndex;
};

using OrientedEdge = Oriented<EdgeId>;
using OrientedFace = Oriented<FaceId>;

/// A handle whose degree is known only at run time (error reports, generic code).
struct ElementId {
  int degree = -1;
  Index index = kInvalidIndex;
  constexpr bool valid() const { return degree >= 0 && index != kInvalidIndex; }
  friend constexpr bool operator==(ElementId, ElementId) = default;
};

inline const char* degreeName(int degree) {
  switch (degree) {
    case 0: return "vertex";
    case 1: return "edge";
    case 2: return "face";
    case 3: return "volume";
    default: return "element";
  }
}

}  // namespace tessella

template <typename Tag>
struct std::hash<tessella::Handle<Tag>> {
  std::size_t operator()(tessella::Handle<Tag> h) const noexcept { return h.index(); }
};
