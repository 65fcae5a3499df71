#include "tessella/sim/sections/tissue_section.hpp"

#include <sstream>
#include <string>

#include "../config/exact_text.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/sim/config/config_error.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::sim {

namespace {

// A typo such as nx: 100000 must not exhaust memory before anything is said.
constexpr double kMaxCells = 1e7;

void declareSeedKeys(Schema& s, const std::string& section, int default_count) {
  s.key(section + ".count", ValueType::Int,
        "Number of seed points (one per cell), drawn uniformly at random with `rng_seed`.")
      .byDefault(std::int64_t{default_count})
      .atLeast(3)
      .atMost(kMaxCells)
      .unlessSet(section + ".seed_file");
  s.key(section + ".seed_file", ValueType::Path,
        "CSV file of seed points instead of random ones: one `x,y` (2D) or `x,y,z` (3D) row per "
        "cell, an optional header row naming every column (a first row mixing names and numbers is an "
        "error); relative to the config file. Give either this or `count`.")
      .whenAbsent("random seeds (`count`)");
  s.key(section + ".lloyd_iterations", ValueType::Int,
        "Lloyd relaxation steps (each moves every seed to its cell's centroid): 0 keeps the raw "
        "Voronoi cells, a few give the more even sizes of real tissues.")
      .byDefault(std::int64_t{0})
      .atLeast(0)
      .atMost(1000);
  s.key(section + ".duplicate_tolerance", ValueType::Float,
        "Seeds closer than this, relative to the domain size, are rejected as duplicates.")
      .byDefault(1e-9)
      .above(0)
      .atMost(0.1);
}

void declareGridCount(Schema& s, const std::string& path, const std::string& doc, int def) {
  s.key(path, ValueType::Int, doc).byDefault(std::int64_t{def}).atLeast(1).atMost(1e5);
}

std::size_t count(const Config& c, const std::string& path) {
  return static_cast<std::size_t>(c.getInt(path));
}

void checkCellCount(const Config& c, const std::string& key, double cells, const std::string& product) {
  if (cells > kMaxCells)
    throw c.errorAt(key, product + " = " + formatValue(cells) + " cells is more than the limit of " +
                             formatValue(kMaxCells));
}

void checkMinMax(const Config& c, const std::string& section) {
  const Vec3 lo = c.getVec(section + ".min"), hi = c.getVec(section + ".max");
  const int n = static_cast<int>(std::get<std::vector<double>>(c.entry(section + ".min").value).size());
  for (int i = 0; i < n; ++i)
    if (!(hi[i] > lo[i]))
      throw c.errorAt(section + ".max",
                      "must exceed " + section + ".min = " + formatValue(c.entry(section + ".min").value) +
                          " in every coordinate, got " + formatValue(c.entry(section + ".max").value));
}

SeedSpec readSeeds(const Config& c, const std::string& section, int dim) {
  SeedSpec seeds;
  seeds.count = count(c, section + ".count");
  if (c.has(section + ".seed_file")) {
    if (c.isGiven(section + ".count"))
      throw c.errorAt(section + ".count", "give either " + section + ".count or " + section +
                                              ".seed_file, not both");
    seeds.file = c.getString(section + ".seed_file");
  } else if (dim == 3 && seeds.count < 4) {
    throw c.errorAt(section + ".count", "a 3D Voronoi tissue needs at least 4 seeds, got " +
                                            std::to_string(seeds.count));
  }
  seeds.options.lloyd_iterations = static_cast<int>(c.getInt(section + ".lloyd_iterations"));
  seeds.options.duplicate_tolerance = c.getFloat(section + ".duplicate_tolerance");
  return seeds;
}

}  // namespace

void declareTissueSection(Schema& s) {
  s.section("tissue", "The initial tissue. `generator` picks one of the subsections below; only that "
                      "one is read (the others may stay in the file, unused).");
  s.key("tissue.generator", ValueType::Enum, "Which generator builds the initial tissue.")
      .oneOf({"rectangular_grid", "hexagonal_grid", "box_grid", "voronoi", "dome", "snapshot", "import"})
      .isRequired();

  s.section("tissue.rectangular_grid", "`nx` x `ny` rectangular cells: a flat 2D tissue.")
      .activeWhen("tissue.generator", {"rectangular_grid"});
  declareGridCount(s, "tissue.rectangular_grid.nx", "Number of cells along x.", 10);
  declareGridCount(s, "tissue.rectangular_grid.ny", "Number of cells along y.", 10);
  s.key("tissue.rectangular_grid.dx", ValueType::Float, "Cell width (along x).").byDefault(1.0).above(0);
  s.key("tissue.rectangular_grid.dy", ValueType::Float, "Cell height (along y).").byDefault(1.0).above(0);
  s.key("tissue.rectangular_grid.origin", ValueType::Vec2, "Lower-left corner of the grid.")
      .byDefault(std::vector<double>{0, 0});

  s.section("tissue.hexagonal_grid",
            "`nx` x `ny` regular hexagons (pointy side up, offset rows): a flat 2D tissue in "
            "which every inner cell has six neighbours.")
      .activeWhen("tissue.generator", {"hexagonal_grid"});
  declareGridCount(s, "tissue.hexagonal_grid.nx", "Number of hexagons per row.", 10);
  declareGridCount(s, "tissue.hexagonal_grid.ny", "Number of rows.", 10);
  s.key("tissue.hexagonal_grid.radius", ValueType::Float,
        "Circumradius of each hexagon (centre to corner); a cell's area is 3*sqrt(3)/2 * radius^2.")
      .byDefault(1.0)
      .above(0);
  s.key("tissue.hexagonal_grid.origin", ValueType::Vec2, "Position of the first hexagon's reference corner.")
      .byDefault(std::vector<double>{0, 0});

  s.section("tissue.box_grid", "`nx` x `ny` x `nz` box cells: a 3D tissue.")
      .activeWhen("tissue.generator", {"box_grid"});
  declareGridCount(s, "tissue.box_grid.nx", "Number of cells along x.", 4);
  declareGridCount(s, "tissue.box_grid.ny", "Number of cells along y.", 4);
  declareGridCount(s, "tissue.box_grid.nz", "Number of cells along z.", 4);
  s.key("tissue.box_grid.dx", ValueType::Float, "Cell size along x.").byDefault(1.0).above(0);
  s.key("tissue.box_grid.dy", ValueType::Float, "Cell size along y.").byDefault(1.0).above(0);
  s.key("tissue.box_grid.dz", ValueType::Float, "Cell size along z.").byDefault(1.0).above(0);
  s.key("tissue.box_grid.origin", ValueType::Vec3, "Lowest corner of the grid.")
      .byDefault(std::vector<double>{0, 0, 0});

  s.section("tissue.voronoi",
            "Voronoi cells of seed points (the dual of their Delaunay triangulation, computed with "
            "CGAL), clipped to a domain: a rectangle or disk gives a flat 2D tissue, a box or ball "
            "a 3D one.")
      .activeWhen("tissue.generator", {"voronoi"});
  s.key("tissue.voronoi.domain", ValueType::Enum,
        "Domain the cells fill; its size is set in the subsection of the same name.")
      .oneOf({"rectangle", "disk", "box", "ball"})
      .byDefault(std::string("rectangle"));
  declareSeedKeys(s, "tissue.voronoi", 100);
  s.section("tissue.voronoi.rectangle", "An axis-aligned rectangle in the z = 0 plane.")
      .activeWhen("tissue.voronoi.domain", {"rectangle"});
  s.key("tissue.voronoi.rectangle.min", ValueType::Vec2, "Lower-left corner.")
      .byDefault(std::vector<double>{0, 0});
  s.key("tissue.voronoi.rectangle.max", ValueType::Vec2, "Upper-right corner (greater than `min` in x and y).")
      .byDefault(std::vector<double>{10, 10});
  s.section("tissue.voronoi.disk", "A disk in the z = 0 plane, approximated by a regular polygon.")
      .activeWhen("tissue.voronoi.domain", {"disk"});
  s.key("tissue.voronoi.disk.center", ValueType::Vec2, "Centre.").byDefault(std::vector<double>{0, 0});
  s.key("tissue.voronoi.disk.radius", ValueType::Float, "Radius.").byDefault(5.0).above(0);
  s.key("tissue.voronoi.disk.boundary_segments", ValueType::Int,
        "Sides of the polygon standing for the circle (areas refer to that polygon).")
      .byDefault(std::int64_t{256})
      .atLeast(8)
      .atMost(1e5);
  s.section("tissue.voronoi.box", "An axis-aligned box.").activeWhen("tissue.voronoi.domain", {"box"});
  s.key("tissue.voronoi.box.min", ValueType::Vec3, "Lowest corner.").byDefault(std::vector<double>{0, 0, 0});
  s.key("tissue.voronoi.box.max", ValueType::Vec3, "Highest corner (greater than `min` in x, y and z).")
      .byDefault(std::vector<double>{4, 4, 4});
  s.section("tissue.voronoi.ball", "A ball, approximated by a subdivided icosahedron.")
      .activeWhen("tissue.voronoi.domain", {"ball"});
  s.key("tissue.voronoi.ball.center", ValueType::Vec3, "Centre.").byDefault(std::vector<double>{0, 0, 0});
  s.key("tissue.voronoi.ball.radius", ValueType::Float, "Radius.").byDefault(2.0).above(0);
  s.key("tissue.voronoi.ball.subdivisions", ValueType::Int,
        "Subdivision level of the icosphere standing for the sphere (20 * 4^level triangles; "
        "volumes refer to that polyhedron).")
      .byDefault(std::int64_t{3})
      .atLeast(0)
      .atMost(7);

  s.section("tissue.dome",
            "A curved sheet of cells on a dome, the usual start of shoot apical meristem models: a "
            "Voronoi tissue of the footprint disk (in the z = 0 plane) lifted vertically onto the "
            "dome surface.")
      .activeWhen("tissue.generator", {"dome"});
  s.key("tissue.dome.shape", ValueType::Enum, "Profile of the dome.")
      .oneOf({"spherical_cap", "paraboloid"})
      .byDefault(std::string("spherical_cap"));
  s.key("tissue.dome.base_radius", ValueType::Float, "Radius of the footprint disk.").byDefault(5.0).above(0);
  s.key("tissue.dome.height", ValueType::Float,
        "Height of the summit above the base plane (a spherical cap needs height <= base_radius).")
      .byDefault(2.5)
      .above(0);
  s.key("tissue.dome.base_center", ValueType::Vec2, "Centre of the footprint disk.")
      .byDefault(std::vector<double>{0, 0});
  declareSeedKeys(s, "tissue.dome", 100);

  s.section("tissue.snapshot",
            "A snapshot written by Tessella (any `.vtu` of a series): the run restarts from it with its "
            "topology, positions, properties and lineage (new cells get lineage ids above every saved "
            "one). The clock starts at the snapshot's time unless `time.start` is given.")
      .activeWhen("tissue.generator", {"snapshot"});
  s.key("tissue.snapshot.file", ValueType::Path, "The `.vtu` file, relative to the config file.").isRequired();

  s.section("tissue.import",
            "A segmented tissue from another tool's file (docs/import.md lists the formats and what is kept): "
            "each cell keeps its original label as the cell property `label` (and `parent` where the file "
            "has one). A malformed file stops the run before it starts, with the file, line or element and "
            "cell label.")
      .activeWhen("tissue.generator", {"import"});
  s.key("tissue.import.file", ValueType::Path, "The file to import, relative to the config file.").isRequired();
  s.key("tissue.import.format", ValueType::Enum,
        "The file's format; `auto` picks it from the extension (and, for `.ply`, from the properties the "
        "file declares).")
      .oneOf(io::importFormatNames())
      .byDefault(std::string("auto"));
  s.key("tissue.import.scale", ValueType::Float,
        "Multiplies every position (a unit conversion); 1 keeps the file's units.")
      .byDefault(1.0)
      .above(0);
  s.key("tissue.import.simplify", ValueType::Float,
        "Douglas-Peucker tolerance (after `scale`) for the wall polylines between junctions; both sides of a "
        "wall get the same polyline. 0 keeps every wall vertex.")
      .byDefault(0.0)
      .atLeast(0);
  s.key("tissue.import.repair", ValueType::Bool,
        "Repair the harmless defects the importer knows (a one-triangle sliver of a cell lying apart from it "
        "goes to its neighbour) and report each; without it they are errors.")
      .byDefault(false);
}

TissueSpec readTissueSection(const Config& c) {
  const std::string& generator = c.getString("tissue.generator");
  if (generator == "rectangular_grid") {
    const std::string p = "tissue.rectangular_grid";
    RectangularGridSpec g{count(c, p + ".nx"), count(c, p + ".ny"), c.getFloat(p + ".dx"),
                          c.getFloat(p + ".dy"), c.getVec(p + ".origin")};
    checkCellCount(c, p + ".nx", double(g.nx) * double(g.ny), "nx * ny");
    return g;
  }
  if (generator == "hexagonal_grid") {
    const std::string p = "tissue.hexagonal_grid";
    HexagonalGridSpec g{count(c, p + ".nx"), count(c, p + ".ny"), c.getFloat(p + ".radius"),
                        c.getVec(p + ".origin")};
    checkCellCount(c, p + ".nx", double(g.nx) * double(g.ny), "nx * ny");
    return g;
  }
  if (generator == "box_grid") {
    const std::string p = "tissue.box_grid";
    BoxGridSpec g{count(c, p + ".nx"), count(c, p + ".ny"), count(c, p + ".nz"), c.getFloat(p + ".dx"),
                  c.getFloat(p + ".dy"), c.getFloat(p + ".dz"), c.getVec(p + ".origin")};
    checkCellCount(c, p + ".nx", double(g.nx) * double(g.ny) * double(g.nz), "nx * ny * nz");
    return g;
  }
  if (generator == "voronoi") {
    const std::string p = "tissue.voronoi";
    const std::string& domain = c.getString(p + ".domain");
    VoronoiSpec v;
    if (domain == "rectangle") {
      checkMinMax(c, p + ".rectangle");
      v.domain = Rectangle{c.getVec(p + ".rectangle.min"), c.getVec(p + ".rectangle.max")};
    } else if (domain == "disk") {
      v.domain = Disk{c.getVec(p + ".disk.center"), c.getFloat(p + ".disk.radius"),
                      static_cast<int>(c.getInt(p + ".disk.boundary_segments"))};
    } else if (domain == "box") {
      checkMinMax(c, p + ".box");
      v.domain = Box{c.getVec(p + ".box.min"), c.getVec(p + ".box.max")};
    } else {
      v.domain = Ball{c.getVec(p + ".ball.center"), c.getFloat(p + ".ball.radius"),
                      static_cast<int>(c.getInt(p + ".ball.subdivisions"))};
    }
    v.seeds = readSeeds(c, p, v.dim());
    return v;
  }
  if (generator == "import") {
    const std::string p = "tissue.import";
    ImportSpec spec{c.getString(p + ".file"),
                    io::ImportOptions{c.getString(p + ".format"), c.getFloat(p + ".scale"),
                                      c.getFloat(p + ".simplify"), c.getBool(p + ".repair")},
                    nullptr};
    try {
      spec.tissue = std::make_shared<const Tissue>(io::importTissue(spec.file, spec.options).tissue);
    } catch (const InputError& e) {
      throw c.errorAt(p + ".file", e.what());
    }
    return spec;
  }
  if (generator == "snapshot") {
    SnapshotSpec snap{c.getString("tissue.snapshot.file"), nullptr, {}, {}};
    try {
      io::Snapshot read = io::readSnapshot(snap.file);
      snap.state = std::move(read.state);
      snap.tissue = std::make_shared<const Tissue>(std::move(read.tissue));
    } catch (const InputError& e) {
      throw c.errorAt("tissue.snapshot.file", e.what());
    }
    return snap;
  }
  // dome
  const std::string p = "tissue.dome";
  DomeSpec d;
  d.dome.shape = c.getString(p + ".shape") == "paraboloid" ? Dome::Shape::Paraboloid : Dome::Shape::SphericalCap;
  d.dome.base_radius = c.getFloat(p + ".base_radius");
  d.dome.height = c.getFloat(p + ".height");
  d.dome.base_center = c.getVec(p + ".base_center");
  if (d.dome.shape == Dome::Shape::SphericalCap && d.dome.height > d.dome.base_radius)
    throw c.errorAt(p + ".height", "a spherical cap cannot be higher than its base radius (" +
                                       formatValue(d.dome.base_radius) + "), got " +
                                       formatValue(d.dome.height) + "; use shape: paraboloid");
  d.seeds = readSeeds(c, p, 2);
  return d;
}

io::RunState domeRunState(const Dome& dome) {
  return {{"dome.shape", dome.shape == Dome::Shape::Paraboloid ? "paraboloid" : "spherical_cap"},
          {"dome.base_radius", formatNumber(dome.base_radius)},
          {"dome.height", formatNumber(dome.height)},
          {"dome.base_center", formatNumber(dome.base_center.x()) + " " + formatNumber(dome.base_center.y()) +
                                   " " + formatNumber(dome.base_center.z())}};
}

namespace {
std::optional<Dome> domeFromRunState(const io::RunState& state) {
  const auto shape = state.find("dome.shape"), radius = state.find("dome.base_radius"),
             height = state.find("dome.height"), center = state.find("dome.base_center");
  if (shape == state.end() || radius == state.end() || height == state.end() || center == state.end())
    return std::nullopt;
  Dome dome;
  if (shape->second != "paraboloid" && shape->second != "spherical_cap") return std::nullopt;
  dome.shape = shape->second == "paraboloid" ? Dome::Shape::Paraboloid : Dome::Shape::SphericalCap;
  std::istringstream words(center->second);
  std::string x, y, z, extra;
  words >> x >> y >> z;
  if (!detail::parseExact(radius->second, dome.base_radius) || !detail::parseExact(height->second, dome.height) ||
      !detail::parseExact(x, dome.base_center.x()) || !detail::parseExact(y, dome.base_center.y()) ||
      !detail::parseExact(z, dome.base_center.z()) || (words >> extra))
    return std::nullopt;
  return dome;
}
}  // namespace

std::optional<Dome> tissueDome(const TissueSpec& spec) {
  if (const auto* dome = std::get_if<DomeSpec>(&spec)) return dome->dome;
  if (const auto* snap = std::get_if<SnapshotSpec>(&spec)) return domeFromRunState(snap->state);
  return std::nullopt;
}

namespace {
struct TissueBuilder {
  std::uint64_t rng_seed;

  Tissue operator()(const RectangularGridSpec& g) const {
    return rectangularGrid(g.nx, g.ny, g.dx, g.dy, g.origin);
  }
  Tissue operator()(const HexagonalGridSpec& g) const {
    return hexagonalGrid(g.nx, g.ny, g.radius, g.origin);
  }
  Tissue operator()(const BoxGridSpec& g) const {
    return boxGrid(g.nx, g.ny, g.nz, g.dx, g.dy, g.dz, g.origin);
  }
  Tissue operator()(const VoronoiSpec& v) const {
    return std::visit(
        [&](const auto& domain) {
          const auto seeds = v.seeds.file.empty() ? randomSeeds(domain, v.seeds.count, rng_seed)
                                                  : readSeedsCsv(v.seeds.file, v.dim());
          return voronoiTissue(seeds, domain, v.seeds.options);
        },
        v.domain);
  }
  Tissue operator()(const DomeSpec& d) const {
    const Disk footprint{d.dome.base_center, d.dome.base_radius};
    const auto seeds = d.seeds.file.empty() ? randomSeeds(footprint, d.seeds.count, rng_seed)
                                            : readSeedsCsv(d.seeds.file, 2);
    return domeTissue(seeds, d.dome, d.seeds.options);
  }
  Tissue operator()(const ImportSpec& s) const {
    if (!s.tissue) return io::importTissue(s.file, s.options).tissue;
    return *s.tissue;
  }
  Tissue operator()(const SnapshotSpec& s) const {
    if (!s.tissue) return io::readTissueVtu(s.file);
    return *s.tissue;
  }
};
}  // namespace

Tissue buildTissue(const TissueSpec& spec, std::uint64_t rng_seed) {
  return std::visit(TissueBuilder{rng_seed}, spec);
}

Tissue buildTissue(const TissueSpec& spec, std::uint64_t rng_seed, const Config& config) {
  try {
    return buildTissue(spec, rng_seed);
  } catch (const ConfigError&) {
    throw;
  } catch (const InputError& e) {
    // Point at the key the bad input came from: the seed file if one was
    // given, else the generator choice.
    std::string key = "tissue.generator";
    const std::string& generator = config.getString("tissue.generator");
    if ((generator == "voronoi" || generator == "dome") &&
        config.has("tissue." + generator + ".seed_file"))
      key = "tissue." + generator + ".seed_file";
    if (generator == "import") key = "tissue.import.file";
    throw config.errorAt(key, e.what());
  }
}

}  // namespace tessella::sim
