// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/tissue_section.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include "../config/exact_text.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/sim/config/config_error.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::sim {

namespace {

std::string sectionOf(const std::string& name) { return "tissue." + name; }

// "0, 1" -> {0, 1}: the integer lists of the label-image keys (a ParamError at `param` otherwise).
std::vector<std::int64_t> integerList(const ParamValues& p, const std::string& param) {
  std::vector<std::int64_t> out;
  std::string text = p.getString(param);
  std::replace(text.begin(), text.end(), ',', ' ');
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    std::size_t used = 0;
    long long value = 0;
    try {
      value = std::stoll(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != word.size())
      throw ParamError(param, "'" + word + "' in '" + p.getString(param) + "' is no integer (give integers "
                              "separated by commas, e.g. \"0, 1\")");
    out.push_back(value);
  }
  return out;
}

// The values given for `params` under `section` (defaults are the params' own:
// completeParams fills them in).
ParamValues givenValues(const Config& c, const std::string& section, const std::vector<ParamSpec>& params) {
  ParamValues values;
  for (const ParamSpec& p : params)
    if (c.isGiven(joinPath(section, p.name))) values.set(p.name, c.entry(joinPath(section, p.name)).value);
  return values;
}

// A section's keys from a parameter table; a group's parameters ("disk.radius")
// go to its subsection, declared before its first parameter.
void declareParams(Schema& s, const std::string& section, const std::vector<ParamSpec>& params,
                   const std::vector<ParamGroup>& groups) {
  std::vector<std::string> declared;
  for (const ParamSpec& p : params) {
    const auto dot = p.name.find('.');
    if (dot != std::string::npos) {
      const std::string group = p.name.substr(0, dot);
      if (std::find(declared.begin(), declared.end(), group) == declared.end()) {
        for (const ParamGroup& g : groups)
          if (g.name == group)
            s.section(joinPath(section, g.name), g.doc).activeWhen(joinPath(section, g.selector), {g.name});
        declared.push_back(group);
      }
    }
    s.key(section, p);
  }
}

}  // namespace

GeneratedShape GeneratorSpec::shape() const { return generators().at(name).make.shape(params); }

const Registry<FileSourceReader>& tissueFileSources() {
  static const Registry<FileSourceReader> sources(
      "tissue source",
      {{"snapshot",
        "A snapshot written by Tessella (any `.vtu` of a series): the run restarts from it with its topology, "
        "positions, properties and lineage (new cells get lineage ids above every saved one). The clock starts "
        "at the snapshot's time unless `time.start` is given.",
        {ParamSpec("file", ParamType::Path, "The `.vtu` file, relative to the config file.")},
        [](const ParamValues& p) -> TissueSpec {
          SnapshotSpec snap{p.getString("file"), nullptr, {}, {}};
          io::Snapshot read = io::readSnapshot(snap.file);
          snap.state = std::move(read.state);
          snap.tissue = std::make_shared<const Tissue>(std::move(read.tissue));
          return snap;
        }},
       {"import",
        "A segmented tissue from another tool's file (docs/import.md lists the formats and what is kept): each "
        "cell keeps its original label as the cell property `label` (and `parent` where the file has one). A "
        "malformed file stops the run before it starts, with the file, line or element and cell label.",
        {ParamSpec("file", ParamType::Path, "The file to import, relative to the config file."),
         ParamSpec("format", ParamType::Enum,
                   "The file's format; `auto` picks it from the extension (and, for `.ply`, from the properties "
                   "the file declares).")
             .oneOf(io::importFormatNames())
             .byDefault(std::string("auto")),
         ParamSpec("scale", ParamType::Float,
                   "Multiplies every position (a unit conversion); 1 keeps the file's units.")
             .byDefault(1.0)
             .above(0),
         ParamSpec("simplify", ParamType::Float,
                   "Douglas-Peucker tolerance (after `scale`) for the wall polylines between junctions; both sides "
                   "of a wall get the same polyline. 0 keeps every wall vertex. Label images: in pixels, 0 keeps every "
                   "corner where the pixel boundary turns.")
             .byDefault(0.0)
             .atLeast(0),
         ParamSpec("repair", ParamType::Bool,
                   "Repair the harmless defects the importer knows (a one-triangle sliver of a cell lying apart "
                   "from it goes to its neighbour) and report each; without it they are errors.")
             .byDefault(false),
         ParamSpec("label_array", ParamType::String,
                   "For `labelled_mesh` and `labelled_vtu`: the face property or cell-data array holding each "
                   "face's cell label (OBJ: the statement `g`, `o` or `usemtl`); `A,B` names two, the cells on "
                   "either side of each face (a 3D tissue). Empty: the first of `label`, `cell_label`, `cell_id`, "
                   "else the pair `label_front`, `label_back`.")
             .byDefault(std::string("")),
         ParamSpec("voxel_size", ParamType::Vec2or3,
                   "Label images: the pixel size [x, y] of a 2D image or the voxel size [x, y, z] of a 3D one, "
                   "overriding the file's (docs/import.md, \"Label images\").")
             .whenAbsent("the pixel size the file gives (1 where it gives none)"),
         ParamSpec("background", ParamType::String,
                   "Label images: the labels that are no cell, integers separated by commas (PlantSeg and MARS "
                   "use 0 and 1).")
             .byDefault(std::string("0, 1")),
         ParamSpec("drop_labels", ParamType::String,
                   "Label images: labels to drop (made background), integers separated by commas.")
             .byDefault(std::string("")),
         ParamSpec("min_cell_size", ParamType::Int,
                   "Label images: labels with fewer pixels are dropped or merged (`small_cells`), each reported; 0 "
                   "keeps every label.")
             .byDefault(std::int64_t{0})
             .atLeast(0),
         ParamSpec("small_cells", ParamType::Enum,
                   "Label images: what happens to a label smaller than `min_cell_size`: `drop` (made background) "
                   "or `merge` (into the neighbour sharing the longest wall).")
             .oneOf({"drop", "merge"})
             .byDefault(std::string("drop")),
         ParamSpec("crop", ParamType::String,
                   "Label images: `x0, y0, x1, y1` keeps the pixels x0 <= i < x1, y0 <= j < y1 only (3D images: "
                   "`x0, y0, z0, x1, y1, z1`); empty keeps the whole image.")
             .byDefault(std::string("")),
         ParamSpec("keep_pieces", ParamType::Bool,
                   "Label images: a label in several disconnected pieces becomes one cell per piece (each keeping "
                   "the label); without it, an error.")
             .byDefault(false)},
        [](const ParamValues& p) -> TissueSpec {
          ImportSpec spec{p.getString("file"),
                          io::ImportOptions{p.getString("format"), p.getFloat("scale"), p.getFloat("simplify"),
                                            p.getBool("repair"), p.getString("label_array")},
                          nullptr};
          if (p.has("voxel_size")) spec.options.image.voxel_size = p.getList("voxel_size");
          spec.options.image.background = integerList(p, "background");
          spec.options.image.drop_labels = integerList(p, "drop_labels");
          spec.options.image.min_cell_size = p.getInt("min_cell_size");
          spec.options.image.small_cells = p.getString("small_cells");
          spec.options.image.crop = integerList(p, "crop");
          spec.options.image.keep_pieces = p.getBool("keep_pieces");
          spec.tissue = std::make_shared<const Tissue>(io::importTissue(spec.file, spec.options).tissue);
          return spec;
        }}});
  return sources;
}

void declareTissueSection(Schema& s) {
  s.section("tissue", "The initial tissue. `generator` picks one of the subsections below; only that "
                      "one is read (the others may stay in the file, unused).");
  std::vector<std::string> names = generators().names();
  for (const std::string& name : tissueFileSources().names()) names.push_back(name);
  s.key("tissue.generator", ValueType::Enum, "Which generator builds the initial tissue.").oneOf(names).isRequired();
  for (const auto& g : generators().entries()) {
    s.section(sectionOf(g.name), g.doc).activeWhen("tissue.generator", {g.name});
    declareParams(s, sectionOf(g.name), g.params, g.make.groups);
  }
  for (const auto& source : tissueFileSources().entries()) {
    s.section(sectionOf(source.name), source.doc).activeWhen("tissue.generator", {source.name});
    declareParams(s, sectionOf(source.name), source.params, {});
  }
}

GeneratorSpec describedGenerator(const Config& c, const std::string& name) {
  const auto& g = generators().at(name);
  return {name, completeParams(g.params, givenValues(c, sectionOf(name), g.params), "generator '" + name + "'")};
}

TissueSpec readTissueSection(const Config& c) {
  const std::string& name = c.getString("tissue.generator");
  const std::string section = sectionOf(name);
  if (const auto* g = generators().find(name)) {
    const GeneratorSpec spec = describedGenerator(c, name);
    const ParamNamer key = [&](const std::string& param) { return joinPath(section, param); };
    try {
      if (g->make.check) g->make.check(spec.params, key);
    } catch (const ParamError& e) {
      throw c.errorAt(key(e.param()), e.what());
    }
    return spec;
  }
  const auto& source = tissueFileSources().at(name);
  const ParamValues values =
      completeParams(source.params, givenValues(c, section, source.params), "tissue source '" + name + "'");
  try {
    return source.make(values);
  } catch (const ParamError& e) {
    throw c.errorAt(joinPath(section, e.param()), e.what());
  } catch (const InputError& e) {
    throw c.errorAt(joinPath(section, "file"), e.what());
  }
}

io::RunState domeRunState(const Dome& dome) {
  return {{"dome.shape", domeShapes().name(dome.shape)},
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
  const auto names = domeShapes().names();
  if (std::find(names.begin(), names.end(), shape->second) == names.end()) return std::nullopt;
  dome.shape = domeShapes().parse(shape->second);
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
  if (const auto* g = std::get_if<GeneratorSpec>(&spec)) {
    const auto& dome = generators().at(g->name).make.dome;
    return dome ? dome(g->params) : std::nullopt;
  }
  if (const auto* snap = std::get_if<SnapshotSpec>(&spec)) return domeFromRunState(snap->state);
  return std::nullopt;
}

namespace {
struct TissueBuilder {
  std::uint64_t rng_seed;

  Tissue operator()(const GeneratorSpec& g) const { return generators().at(g.name).make.build(g.params, rng_seed); }
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
    // A generator blames a parameter (a seed file) ...
    const auto* blamed = dynamic_cast<const ParamError*>(&e);
    if (const auto* g = std::get_if<GeneratorSpec>(&spec); g && blamed)
      throw config.errorAt(joinPath(sectionOf(g->name), blamed->param()), e.what());
    // Else the imported file, or the generator choice.
    throw config.errorAt(std::holds_alternative<ImportSpec>(spec) ? "tissue.import.file" : "tissue.generator",
                         e.what());
  }
}

}  // namespace tessella::sim
