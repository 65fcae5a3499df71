// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The generator table (generator_registry.hpp). Each entry's parameter list
// is the reference of its YAML subsection in docs/config.md, in this order.

#include "tessella/generators/generator_registry.hpp"

#include <string>
#include <utility>
#include <vector>

#include "tessella/generators/dome.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella {

Tissue GeneratorFactory::operator()(const ParamValues& params, std::uint64_t rng_seed) const {
  if (check) check(params, [](const std::string& p) { return p; });
  return build(params, rng_seed);
}

namespace {

ParamSpec gridCount(const std::string& name, const std::string& doc, int fallback) {
  return ParamSpec(name, ParamType::Int, doc).byDefault(std::int64_t{fallback}).atLeast(1).atMost(1e5);
}

std::size_t count(const ParamValues& p, const std::string& name) {
  return static_cast<std::size_t>(p.getInt(name));
}

void checkCellCount(const ParamValues& p, const std::vector<std::string>& counts) {
  double cells = 1;
  std::string product;
  for (const std::string& n : counts) {
    cells *= static_cast<double>(p.getInt(n));
    product += (product.empty() ? "" : " * ") + n;
  }
  if (cells > kMaxGeneratedCells)
    throw ParamError(counts.front(), product + " = " + formatParamValue(cells) + " cells is more than the limit of " +
                                         formatParamValue(kMaxGeneratedCells));
}

// --- Seed points of Voronoi and dome tissues ---------------------------------

std::vector<ParamSpec> seedParams() {
  return {
      ParamSpec("count", ParamType::Int,
                "Number of seed points (one per cell), drawn uniformly at random with `rng_seed`.")
          .byDefault(std::int64_t{100})
          .atLeast(3)
          .atMost(kMaxGeneratedCells)
          .unlessSet("seed_file"),
      ParamSpec("seed_file", ParamType::Path,
                "CSV file of seed points instead of random ones: one `x,y` (2D) or `x,y,z` (3D) row per "
                "cell, an optional header row naming every column (a first row mixing names and numbers is an "
                "error); relative to the config file. Give either this or `count`.")
          .whenAbsent("random seeds (`count`)"),
      ParamSpec("lloyd_iterations", ParamType::Int,
                "Lloyd relaxation steps (each moves every seed to its cell's centroid): 0 keeps the raw "
                "Voronoi cells, a few give the more even sizes of real tissues.")
          .byDefault(std::int64_t{0})
          .atLeast(0)
          .atMost(1000),
      ParamSpec("duplicate_tolerance", ParamType::Float,
                "Seeds closer than this, relative to the domain size, are rejected as duplicates.")
          .byDefault(1e-9)
          .above(0)
          .atMost(0.1),
  };
}

void checkSeeds(const ParamValues& p, const ParamNamer& key, int dim) {
  if (p.has("seed_file")) {
    if (p.has("count"))
      throw ParamError("count", "give either " + key("count") + " or " + key("seed_file") + ", not both");
  } else if (dim == 3 && p.getInt("count") < 4) {
    throw ParamError("count", "a 3D Voronoi tissue needs at least 4 seeds, got " + std::to_string(p.getInt("count")));
  }
}

VoronoiOptions voronoiOptions(const ParamValues& p) {
  VoronoiOptions options;
  options.lloyd_iterations = static_cast<int>(p.getInt("lloyd_iterations"));
  options.duplicate_tolerance = p.getFloat("duplicate_tolerance");
  return options;
}

// Random seeds drawn in `domain`, or the seed file's.
template <typename Domain>
std::vector<Vec3> seedPoints(const ParamValues& p, const Domain& domain, int dim, std::uint64_t rng_seed) {
  if (p.has("seed_file")) return readSeedsCsv(p.getString("seed_file"), dim);
  return randomSeeds(domain, count(p, "count"), rng_seed);
}

// A tissue made from seed points: what goes wrong with seeds read from a file
// (malformed, outside the domain, duplicates) is blamed on the file.
template <typename Make>
Tissue fromSeeds(const ParamValues& p, Make&& make) {
  if (p.has("seed_file")) return blameParam("seed_file", make);
  return make();
}

// --- Voronoi domains: a table of their own, read by the voronoi entry --------

struct DomainFactory {
  int dim = 2;
  /// The Voronoi tissue of the seeds the voronoi parameters `seeds` give, in
  /// the domain its own parameters `domain` give.
  std::function<Tissue(const ParamValues& domain, const ParamValues& seeds, std::uint64_t rng_seed)> build;
  /// The domain is given by corners `min` and `max`, which must be in order.
  bool has_min_max = false;
};

template <typename Domain>
Tissue voronoiIn(const Domain& domain, const ParamValues& seeds, int dim, std::uint64_t rng_seed) {
  return fromSeeds(seeds, [&] {
    return voronoiTissue(seedPoints(seeds, domain, dim, rng_seed), domain, voronoiOptions(seeds));
  });
}

const Registry<DomainFactory>& voronoiDomains() {
  static const Registry<DomainFactory> domains(
      "Voronoi domain",
      {{"rectangle",
        "An axis-aligned rectangle in the z = 0 plane.",
        {ParamSpec("min", ParamType::Vec2, "Lower-left corner.").byDefault(std::vector<double>{0, 0}),
         ParamSpec("max", ParamType::Vec2, "Upper-right corner (greater than `min` in x and y).")
             .byDefault(std::vector<double>{10, 10})},
        {2,
         [](const ParamValues& d, const ParamValues& s, std::uint64_t rng) {
           return voronoiIn(Rectangle{d.getVec3("min"), d.getVec3("max")}, s, 2, rng);
         },
         true}},
       {"disk",
        "A disk in the z = 0 plane, approximated by a regular polygon.",
        {ParamSpec("center", ParamType::Vec2, "Centre.").byDefault(std::vector<double>{0, 0}),
         ParamSpec("radius", ParamType::Float, "Radius.").byDefault(5.0).above(0),
         ParamSpec("boundary_segments", ParamType::Int,
                   "Sides of the polygon standing for the circle (areas refer to that polygon).")
             .byDefault(std::int64_t{256})
             .atLeast(8)
             .atMost(1e5)},
        {2,
         [](const ParamValues& d, const ParamValues& s, std::uint64_t rng) {
           return voronoiIn(Disk{d.getVec3("center"), d.getFloat("radius"),
                                 static_cast<int>(d.getInt("boundary_segments"))},
                            s, 2, rng);
         },
         false}},
       {"box",
        "An axis-aligned box.",
        {ParamSpec("min", ParamType::Vec3, "Lowest corner.").byDefault(std::vector<double>{0, 0, 0}),
         ParamSpec("max", ParamType::Vec3, "Highest corner (greater than `min` in x, y and z).")
             .byDefault(std::vector<double>{4, 4, 4})},
        {3,
         [](const ParamValues& d, const ParamValues& s, std::uint64_t rng) {
           return voronoiIn(Box{d.getVec3("min"), d.getVec3("max")}, s, 3, rng);
         },
         true}},
       {"ball",
        "A ball, approximated by a subdivided icosahedron.",
        {ParamSpec("center", ParamType::Vec3, "Centre.").byDefault(std::vector<double>{0, 0, 0}),
         ParamSpec("radius", ParamType::Float, "Radius.").byDefault(2.0).above(0),
         ParamSpec("subdivisions", ParamType::Int,
                   "Subdivision level of the icosphere standing for the sphere (20 * 4^level triangles; "
                   "volumes refer to that polyhedron).")
             .byDefault(std::int64_t{3})
             .atLeast(0)
             .atMost(7)},
        {3,
         [](const ParamValues& d, const ParamValues& s, std::uint64_t rng) {
           return voronoiIn(Ball{d.getVec3("center"), d.getFloat("radius"),
                                 static_cast<int>(d.getInt("subdivisions"))},
                            s, 3, rng);
         },
         false}}});
  return domains;
}

// The voronoi entry's parameters: the domain choice, the seed parameters,
// then every domain's as "<domain>.<leaf>".
std::vector<ParamSpec> voronoiParams() {
  std::vector<ParamSpec> params{ParamSpec("domain", ParamType::Enum,
                                          "Domain the cells fill; its size is set in the subsection of the same name.")
                                    .oneOf(voronoiDomains().names())
                                    .byDefault(std::string("rectangle"))};
  for (ParamSpec& s : seedParams()) params.push_back(std::move(s));
  for (const auto& domain : voronoiDomains().entries())
    for (ParamSpec p : domain.params) {
      p.name = domain.name + "." + p.name;
      params.push_back(std::move(p));
    }
  return params;
}

std::vector<ParamGroup> voronoiGroups() {
  std::vector<ParamGroup> groups;
  for (const auto& domain : voronoiDomains().entries()) groups.push_back({domain.name, domain.doc, "domain"});
  return groups;
}

// The parameters of group `prefix` ("disk.radius" -> "radius"), and the rest.
ParamValues groupValues(const ParamValues& p, const std::string& prefix) {
  ParamValues out;
  for (const auto& [name, value] : p.all())
    if (name.rfind(prefix + ".", 0) == 0) out.set(name.substr(prefix.size() + 1), value);
  return out;
}

void checkVoronoi(const ParamValues& p, const ParamNamer& key) {
  const std::string& name = p.getString("domain");
  const auto& domain = voronoiDomains().at(name);
  if (domain.make.has_min_max) {
    const auto &lo = p.getList(name + ".min"), &hi = p.getList(name + ".max");
    for (std::size_t i = 0; i < lo.size(); ++i)
      if (!(hi[i] > lo[i]))
        throw ParamError(name + ".max", "must exceed " + key(name + ".min") + " = " + formatParamValue(lo) +
                                            " in every coordinate, got " + formatParamValue(hi));
  }
  checkSeeds(p, key, domain.make.dim);
}

// --- Dome ---------------------------------------------------------------------

Dome domeOf(const ParamValues& p) {
  Dome dome;
  dome.shape = domeShapes().parse(p.getString("shape"));
  dome.base_radius = p.getFloat("base_radius");
  dome.height = p.getFloat("height");
  dome.base_center = p.getVec3("base_center");
  return dome;
}

std::vector<ParamSpec> domeParams() {
  std::vector<ParamSpec> params{
      ParamSpec("shape", ParamType::Enum, "Profile of the dome.")
          .oneOf(domeShapes().names())
          .byDefault(domeShapes().name(Dome::Shape::SphericalCap)),
      ParamSpec("base_radius", ParamType::Float, "Radius of the footprint disk.").byDefault(5.0).above(0),
      ParamSpec("height", ParamType::Float,
                "Height of the summit above the base plane (a spherical cap needs height <= base_radius).")
          .byDefault(2.5)
          .above(0),
      ParamSpec("base_center", ParamType::Vec2, "Centre of the footprint disk.").byDefault(std::vector<double>{0, 0}),
  };
  for (ParamSpec& s : seedParams()) params.push_back(std::move(s));
  return params;
}

void checkDomeParams(const ParamValues& p, const ParamNamer& key) {
  const Dome dome = domeOf(p);
  if (dome.shape == Dome::Shape::SphericalCap && dome.height > dome.base_radius)
    throw ParamError("height", "a spherical cap cannot be higher than its base radius (" +
                                   formatParamValue(dome.base_radius) + "), got " + formatParamValue(dome.height) +
                                   "; use shape: " + domeShapes().name(Dome::Shape::Paraboloid));
  checkSeeds(p, key, 2);
}

Tissue buildDome(const ParamValues& p, std::uint64_t rng_seed) {
  const Dome dome = domeOf(p);
  const Disk footprint{dome.base_center, dome.base_radius};
  return fromSeeds(p, [&] { return domeTissue(seedPoints(p, footprint, 2, rng_seed), dome, voronoiOptions(p)); });
}

}  // namespace

const GeneratorRegistry& generators() {
  static const GeneratorRegistry table(
      "generator",
      {{"rectangular_grid",
        "`nx` x `ny` rectangular cells: a flat 2D tissue.",
        {gridCount("nx", "Number of cells along x.", 10), gridCount("ny", "Number of cells along y.", 10),
         ParamSpec("dx", ParamType::Float, "Cell width (along x).").byDefault(1.0).above(0),
         ParamSpec("dy", ParamType::Float, "Cell height (along y).").byDefault(1.0).above(0),
         ParamSpec("origin", ParamType::Vec2, "Lower-left corner of the grid.").byDefault(std::vector<double>{0, 0})},
        {.build =
             [](const ParamValues& p, std::uint64_t) {
               return rectangularGrid(count(p, "nx"), count(p, "ny"), p.getFloat("dx"), p.getFloat("dy"),
                                      p.getVec3("origin"));
             },
         .shape = [](const ParamValues&) { return GeneratedShape{2, Embedding::Planar, ""}; },
         .check = [](const ParamValues& p, const ParamNamer&) { checkCellCount(p, {"nx", "ny"}); }}},
       {"hexagonal_grid",
        "`nx` x `ny` regular hexagons (pointy side up, offset rows): a flat 2D tissue in which every inner cell "
        "has six neighbours.",
        {gridCount("nx", "Number of hexagons per row.", 10), gridCount("ny", "Number of rows.", 10),
         ParamSpec("radius", ParamType::Float,
                   "Circumradius of each hexagon (centre to corner); a cell's area is 3*sqrt(3)/2 * radius^2.")
             .byDefault(1.0)
             .above(0),
         ParamSpec("origin", ParamType::Vec2, "Position of the first hexagon's reference corner.")
             .byDefault(std::vector<double>{0, 0})},
        {.build =
             [](const ParamValues& p, std::uint64_t) {
               return hexagonalGrid(count(p, "nx"), count(p, "ny"), p.getFloat("radius"), p.getVec3("origin"));
             },
         .shape = [](const ParamValues&) { return GeneratedShape{2, Embedding::Planar, ""}; },
         .check = [](const ParamValues& p, const ParamNamer&) { checkCellCount(p, {"nx", "ny"}); }}},
       {"box_grid",
        "`nx` x `ny` x `nz` box cells: a 3D tissue.",
        {gridCount("nx", "Number of cells along x.", 4), gridCount("ny", "Number of cells along y.", 4),
         gridCount("nz", "Number of cells along z.", 4),
         ParamSpec("dx", ParamType::Float, "Cell size along x.").byDefault(1.0).above(0),
         ParamSpec("dy", ParamType::Float, "Cell size along y.").byDefault(1.0).above(0),
         ParamSpec("dz", ParamType::Float, "Cell size along z.").byDefault(1.0).above(0),
         ParamSpec("origin", ParamType::Vec3, "Lowest corner of the grid.").byDefault(std::vector<double>{0, 0, 0})},
        {.build =
             [](const ParamValues& p, std::uint64_t) {
               return boxGrid(count(p, "nx"), count(p, "ny"), count(p, "nz"), p.getFloat("dx"), p.getFloat("dy"),
                              p.getFloat("dz"), p.getVec3("origin"));
             },
         .shape = [](const ParamValues&) { return GeneratedShape{3, Embedding::Volume, ""}; },
         .check = [](const ParamValues& p, const ParamNamer&) { checkCellCount(p, {"nx", "ny", "nz"}); }}},
       {"cylinder",
        "A cylindrical sheet: `around` x `along` quad cells, a rectangular grid wrapped onto a cylinder about the "
        "vertical axis through `origin` (both ends open; a curved 2D tissue).",
        {ParamSpec("around", ParamType::Int, "Number of cells around.")
             .byDefault(std::int64_t{16})
             .atLeast(3)
             .atMost(1e5),
         gridCount("along", "Number of cells along the axis.", 8),
         ParamSpec("radius", ParamType::Float, "Radius of the cylinder.").byDefault(1.0).above(0),
         ParamSpec("length", ParamType::Float, "Length of the cylinder (along z).").byDefault(2.0).above(0),
         ParamSpec("origin", ParamType::Vec3, "Centre of the bottom ring.").byDefault(std::vector<double>{0, 0, 0})},
        {.build =
             [](const ParamValues& p, std::uint64_t) {
               return cylinderGrid(count(p, "around"), count(p, "along"), p.getFloat("radius"),
                                   p.getFloat("length"), p.getVec3("origin"));
             },
         .shape = [](const ParamValues&) { return GeneratedShape{2, Embedding::Surface, ""}; },
         .check = [](const ParamValues& p, const ParamNamer&) { checkCellCount(p, {"around", "along"}); }}},
       {"voronoi",
        "Voronoi cells of seed points (the dual of their Delaunay triangulation, computed with CGAL), clipped to "
        "a domain: a rectangle or disk gives a flat 2D tissue, a box or ball a 3D one.",
        voronoiParams(),
        {.build =
             [](const ParamValues& p, std::uint64_t rng_seed) {
               const std::string& domain = p.getString("domain");
               return voronoiDomains().at(domain).make.build(groupValues(p, domain), p, rng_seed);
             },
         .shape =
             [](const ParamValues& p) {
               const int dim = voronoiDomains().at(p.getString("domain")).make.dim;
               return GeneratedShape{dim, dim == 2 ? Embedding::Planar : Embedding::Volume, "domain"};
             },
         .check = checkVoronoi,
         .groups = voronoiGroups()}},
       {"dome",
        "A curved sheet of cells on a dome, the usual start of shoot apical meristem models: a Voronoi tissue of "
        "the footprint disk (in the z = 0 plane) lifted vertically onto the dome surface.",
        domeParams(),
        {.build = buildDome,
         .shape = [](const ParamValues&) { return GeneratedShape{2, Embedding::Surface, ""}; },
         .check = checkDomeParams,
         .dome = [](const ParamValues& p) { return std::optional<Dome>(domeOf(p)); }}}});
  return table;
}

}  // namespace tessella
