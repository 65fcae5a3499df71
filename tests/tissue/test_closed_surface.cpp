// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The closed-surface check of addVolume / addVolumes (a table of edge uses):
// a surface passes exactly when every edge is used once in each direction,
// and a failing one names its lowest bad edge -- both compared with a plain
// count of the uses per edge.
#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tessella/tissue/cell_complex.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;

namespace {

// The faces of a prism over an n-gon (bottom, top, n sides), as loops.
std::vector<std::vector<Index>> prismLoops(int n) {
  std::vector<std::vector<Index>> faces;
  std::vector<Index> bottom, top;
  for (int k = n - 1; k >= 0; --k) bottom.push_back(static_cast<Index>(k));
  for (int k = 0; k < n; ++k) top.push_back(static_cast<Index>(n + k));
  faces.push_back(bottom);
  faces.push_back(top);
  for (int k = 0; k < n; ++k) {
    const Index a = static_cast<Index>(k), b = static_cast<Index>((k + 1) % n);
    faces.push_back({a, b, static_cast<Index>(n + b), static_cast<Index>(n + a)});
  }
  return faces;
}

CellComplex prismFaces(int n) {
  std::vector<Index> offsets{0}, items;
  for (const auto& loop : prismLoops(n)) {
    items.insert(items.end(), loop.begin(), loop.end());
    offsets.push_back(static_cast<Index>(items.size()));
  }
  return CellComplex::fromLoops(3, 2 * static_cast<std::size_t>(n), offsets, items);
}

// The lowest edge not used exactly once in each direction, by a plain count
// (kInvalidIndex: the surface is closed).
Index lowestBadEdge(const CellComplex& c, const std::vector<OrientedFace>& faces) {
  std::map<Index, std::pair<int, int>> uses;
  for (const OrientedFace& of : faces)
    for (const OrientedEdge& oe : c.faceEdges(of.handle())) {
      auto& u = uses[oe.handle().index()];
      (oe.reversed() == of.reversed() ? u.first : u.second)++;
    }
  for (const auto& [e, u] : uses)
    if (u.first != 1 || u.second != 1) return e;
  return kInvalidIndex;
}

// The volume's faces: face k reversed when `flip[k]`, face `drop` left out.
std::vector<OrientedFace> surface(std::size_t nf, std::size_t flip, std::size_t drop) {
  std::vector<OrientedFace> faces;
  for (std::size_t k = 0; k < nf; ++k)
    if (k != drop) faces.emplace_back(FaceId(static_cast<Index>(k)), k == flip);
  return faces;
}

// Runs `add`, which must refuse an open surface naming edge `bad`; returns the error's element.
template <typename Add>
ElementId refusedAtEdge(Add&& add, Index bad) {
  try {
    add();
  } catch (const TopologyError& e) {
    CHECK(std::string(e.what()).ends_with("at edge " + std::to_string(bad)));
    return e.element();
  }
  FAIL("an open surface was accepted");
  return {};
}

}  // namespace

TEST_CASE("addVolume accepts a closed surface and names the lowest bad edge of an open one",
          "[tissue][closed_surface]") {
  for (int n : {3, 4, 7, 40, 200}) {  // up to 802 edge uses: the table grows
    const std::size_t nf = static_cast<std::size_t>(n) + 2;
    const std::size_t none = nf;
    for (std::size_t flip = 0; flip <= nf; ++flip)
      for (std::size_t drop : {none, std::size_t{0}, nf - 1}) {
        if (flip == drop) continue;
        CellComplex c = prismFaces(n);
        const std::vector<OrientedFace> faces = surface(nf, flip, drop);
        const Index bad = lowestBadEdge(c, faces);
        INFO("n " << n << " flip " << flip << " drop " << drop);
        if (bad == kInvalidIndex) {
          REQUIRE(flip == none);
          REQUIRE(drop == none);
          CHECK(c.addVolume(faces).index() == 0);
          continue;
        }
        refusedAtEdge([&] { c.addVolume(faces); }, bad);
      }
  }
}

namespace {

// The faces of two disjoint n-gonal prisms as vertex loops in CSR form (offsets, items): prism 1's
// vertices are prism 0's plus 2 n.
std::pair<std::vector<Index>, std::vector<Index>> twoPrismLoops(int n) {
  std::vector<Index> offsets{0}, items;
  for (int copy = 0; copy < 2; ++copy)
    for (const auto& loop : prismLoops(n)) {
      for (Index v : loop) items.push_back(v + static_cast<Index>(copy * 2 * n));
      offsets.push_back(static_cast<Index>(items.size()));
    }
  return {offsets, items};
}

}  // namespace

TEST_CASE("addVolumes checks every volume's surface like addVolume", "[tissue][closed_surface]") {
  // Two prisms' faces in one complex: volume 0 closed, volume 1 with face `flip` reversed.
  for (int n : {5, 60}) {
    const std::size_t nf = static_cast<std::size_t>(n) + 2;
    const auto [offsets, items] = twoPrismLoops(n);
    for (std::size_t flip : {nf, std::size_t{0}, nf / 2}) {
      CellComplex c = CellComplex::fromLoops(3, 4 * static_cast<std::size_t>(n), offsets, items);
      std::vector<OrientedFace> faces = surface(nf, nf, nf);
      for (std::size_t k = 0; k < nf; ++k) faces.emplace_back(FaceId(static_cast<Index>(nf + k)), k == flip);
      const std::vector<Index> volume_offsets{0, static_cast<Index>(nf), static_cast<Index>(2 * nf)};
      const Index bad =
          lowestBadEdge(c, std::vector<OrientedFace>(faces.begin() + static_cast<std::ptrdiff_t>(nf), faces.end()));
      INFO("n " << n << " flip " << flip);
      if (flip == nf) {
        REQUIRE(bad == kInvalidIndex);
        c.addVolumes(volume_offsets, faces);
        CHECK(c.volumeFaces(VolumeId(1)).size() == nf);
        continue;
      }
      CHECK(refusedAtEdge([&] { c.addVolumes(volume_offsets, faces); }, bad).index == 1);
    }
  }
}

TEST_CASE("a surface of 2^16 edge uses or more is checked by sorting its uses", "[tissue][closed_surface]") {
  // A prism over an 11000-gon: 6 * 11000 = 66000 edge uses, past the table's 16-bit counts.
  const int n = 11000;
  const std::size_t nf = static_cast<std::size_t>(n) + 2;
  const std::size_t none = nf;
  for (std::size_t flip : {none, std::size_t{0}, nf / 2, nf - 1})
    for (std::size_t drop : {none, std::size_t{1}}) {
      CellComplex c = prismFaces(n);
      const std::vector<OrientedFace> faces = surface(nf, flip, drop);
      const Index bad = lowestBadEdge(c, faces);
      INFO("flip " << flip << " drop " << drop);
      if (bad == kInvalidIndex) {
        REQUIRE(flip == none);
        REQUIRE(drop == none);
        CHECK(c.addVolume(faces).index() == 0);
        const std::vector<Index> offsets{0, static_cast<Index>(faces.size())};
        CellComplex d = prismFaces(n);
        d.addVolumes(offsets, faces);
        CHECK(d.volumeFaces(VolumeId(0)).size() == nf);
        continue;
      }
      refusedAtEdge([&] { c.addVolume(faces); }, bad);
    }
}

TEST_CASE("addVolumes trusts closed-by-construction volumes for their surface only", "[tissue][closed_surface]") {
  const int n = 6;
  const std::size_t nf = static_cast<std::size_t>(n) + 2;
  const auto [offsets, items] = twoPrismLoops(n);
  auto faces = [&](std::size_t flip1) {  // volume 0: prism 0; volume 1: prism 1 with face flip1 reversed
    std::vector<OrientedFace> f = surface(nf, nf, nf);
    for (std::size_t k = 0; k < nf; ++k) f.emplace_back(FaceId(static_cast<Index>(nf + k)), k == flip1);
    return f;
  };
  const std::vector<Index> volume_offsets{0, static_cast<Index>(nf), static_cast<Index>(2 * nf)};
  auto complex = [&] { return CellComplex::fromLoops(3, 4 * static_cast<std::size_t>(n), offsets, items); };
  const std::vector<std::uint8_t> both{1, 1}, first{1, 0};

  // Closed volumes: flagged or not, the same complex.
  CellComplex checked = complex(), trusted = complex();
  checked.addVolumes(volume_offsets, faces(nf));
  trusted.addVolumes(volume_offsets, faces(nf), both);
  CHECK(checked.layout() == trusted.layout());

  // One flag per volume.
  CellComplex c = complex();
  CHECK_THROWS_WITH(c.addVolumes(volume_offsets, faces(nf), std::vector<std::uint8_t>{1}),
                    Catch::Contains("1 closed-by-construction flags for 2 volumes"));
  CHECK(c.count(3) == 0);

  // An open surface in a volume that is not flagged is still refused.
  CHECK_THROWS_WITH(c.addVolumes(volume_offsets, faces(3), first), Catch::Contains("volume 1: surface is not closed"));
  CHECK(c.count(3) == 0);

  // Flagged volumes still get every other check: a face twice, too few faces, a face in a third volume.
  std::vector<OrientedFace> twice = faces(nf);
  twice[1] = twice[0];
  CHECK_THROWS_WITH(c.addVolumes(volume_offsets, twice, both), Catch::Contains("volume 0 uses face 0 twice"));
  const std::vector<Index> short_offsets{0, 3, static_cast<Index>(3 + nf)};
  std::vector<OrientedFace> short_faces = surface(nf, nf, nf);
  short_faces.erase(short_faces.begin() + 3, short_faces.begin() + static_cast<std::ptrdiff_t>(nf));
  for (std::size_t k = 0; k < nf; ++k) short_faces.emplace_back(FaceId(static_cast<Index>(nf + k)), false);
  CHECK_THROWS_WITH(c.addVolumes(short_offsets, short_faces, both), Catch::Contains("needs at least 4 faces, got 3"));
  CHECK(c.count(3) == 0);
  c.addVolumes(volume_offsets, faces(nf), both);
  std::vector<OrientedFace> prism0_twice = surface(nf, nf, nf);  // two more volumes on prism 0's faces
  const std::vector<OrientedFace> prism0 = prism0_twice;
  prism0_twice.insert(prism0_twice.end(), prism0.begin(), prism0.end());
  CHECK_THROWS_WITH(c.addVolumes(volume_offsets, prism0_twice, both),
                    Catch::Contains("volume 3: face 0 already bounds two volumes"));
  CHECK(c.count(3) == 2);

  // The flag is a promise: a flagged open surface is refused only where every surface is checked
  // (debug and paranoid builds); elsewhere it is built, unchecked.
  CellComplex open = complex();
#if !defined(NDEBUG) || defined(TESSELLA_PARANOID)
  CHECK_THROWS_WITH(open.addVolumes(volume_offsets, faces(3), both), Catch::Contains("surface is not closed"));
#else
  open.addVolumes(volume_offsets, faces(3), both);
  CHECK(open.count(3) == 2);
  CHECK(lowestBadEdge(open, faces(3)) != kInvalidIndex);  // (as built: open)
#endif
}
