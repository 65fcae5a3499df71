// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/primordia_output.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::sim {

namespace {
void writeAll(const std::string& path, const std::vector<PrimordiumRecord>& records) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::out | std::ios::trunc);
    out << primordiaCsv(records);
    out.flush();
    if (!out) throw InputError("cannot write '" + temporary + "': " + std::strerror(errno));
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) throw InputError("cannot write '" + path + "': " + ec.message());
}
}  // namespace

std::string primordiaCsv(const std::vector<PrimordiumRecord>& records) {
  std::string text = "id,time,lineage_id,x,y,z,angle_deg,radius,distance,divergence_deg\n";
  for (const PrimordiumRecord& r : records)
    text += std::to_string(r.id) + "," + formatNumber(r.time) + "," + std::to_string(r.lineage) + "," +
            formatNumber(r.position.x()) + "," + formatNumber(r.position.y()) + "," + formatNumber(r.position.z()) +
            "," + formatNumber(r.angle_deg) + "," + formatNumber(r.radius) + "," + formatNumber(r.distance) + "," +
            (std::isnan(r.divergence_deg) ? std::string() : formatNumber(r.divergence_deg)) + "\n";
  return text;
}

const NetworkStage* attachPrimordiaOutput(Simulation& simulation, const std::string& directory) {
  const NetworkStage* stage = nullptr;
  for (std::size_t i = 0; i < simulation.numStages() && !stage; ++i)
    if (const auto* n = dynamic_cast<const NetworkStage*>(&simulation.stage(i)); n && n->spec().primordia.enabled())
      stage = n;
  if (!stage) return nullptr;
  const std::string path = (std::filesystem::path(directory) / kPrimordiaName).string();
  writeAll(path, stage->primordia());
  auto written = std::make_shared<std::size_t>(stage->primordia().size());
  simulation.onStep([stage, path, written](const Simulation&) {
    if (stage->primordia().size() == *written) return;
    writeAll(path, stage->primordia());
    *written = stage->primordia().size();
  });
  return stage;
}

}  // namespace tessella::sim
