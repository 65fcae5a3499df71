// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/reaction_set.hpp"

#include <muParser.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "batch_expression.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::networks {

struct ReactionSet::Workspace {
  std::vector<detail::BatchExpression::Column> members, columns;
  std::vector<double> block = std::vector<double>(detail::BatchExpression::kBlock, 0.0);
};

ReactionSet::ReactionSet(const NetworkModel& model)
    : properties_(model.cell_properties),
      conc_(model.species.size(), 0.0),
      props_(model.cell_properties.size(), 0.0),
      neighbourhood_(2 * model.species.size(), 0.0),
      uses_sum_(model.species.size(), false),
      uses_mean_(model.species.size(), false),
      reads_(model.species.size() * model.species.size(), 0),
      reads_neighbourhood_(2 * model.species.size() * model.species.size(), 0),
      parser_of_(model.species.size(), -1),
      work_(std::make_unique<Workspace>()) {
  for (const NetworkSpecies& s : model.species) {
    species_.push_back(s.name);
    expressions_.push_back(s.reaction);
  }
  for (std::size_t s = 0; s < model.species.size(); ++s) {
    if (model.species[s].reaction.empty()) continue;
    auto parser = std::make_unique<mu::Parser>();
    try {
      for (std::size_t v = 0; v < species_.size(); ++v) {
        parser->DefineVar(species_[v], &conc_[v]);
        parser->DefineVar("sum_" + species_[v], &neighbourhood_[v]);
        parser->DefineVar("mean_" + species_[v], &neighbourhood_[species_.size() + v]);
      }
      // The parameters do not change: as constants, muparser folds what only depends on them.
      for (const auto& [name, value] : model.parameters) parser->DefineConst(name, value);
      for (std::size_t v = 0; v < properties_.size(); ++v) parser->DefineVar(properties_[v], &props_[v]);
      parser->DefineVar("measure", &measure_);
      parser->DefineVar("x", &x_);
      parser->DefineVar("y", &y_);
      parser->DefineVar("z", &z_);
      parser->DefineVar("t", &t_);
      parser->SetExpr(model.species[s].reaction);
      parser->Eval();  // forces the parse: syntax errors and unknown names surface here
      const auto used = parser->GetUsedVar();
      const std::size_t S = species_.size();
      for (std::size_t v = 0; v < S; ++v) {
        if (used.count("sum_" + species_[v])) {
          uses_sum_[v] = true;
          reads_neighbourhood_[(s * 2) * S + v] = true;
        }
        if (used.count("mean_" + species_[v])) {
          uses_mean_[v] = true;
          reads_neighbourhood_[(s * 2 + 1) * S + v] = true;
        }
        reads_[s * S + v] = used.count(species_[v]) ? 1 : 0;
      }
    } catch (const mu::Parser::exception_type& e) {
      const std::string token = e.GetToken().empty() ? "" : "near '" + e.GetToken() + "', ";
      throw InputError("network: reaction of species '" + species_[s] + "', \"" + model.species[s].reaction +
                       "\": " + e.GetMsg() + " (" + token + "at position " + std::to_string(e.GetPos()) +
                       "; the variables are the species, the parameters, the cell properties named, measure, x, "
                       "y, z, t, and sum_<species> and mean_<species>)");
    }
    parser_of_[s] = static_cast<int>(parsers_.size());
    batch_.push_back(std::make_unique<detail::BatchExpression>(*parser, variables()));
    parsers_.push_back(std::move(parser));
    target_.push_back(s);
  }
  // Each variable's column when the batch programs read the members (one cell: stride 0).
  for (double* v : variables()) work_->members.push_back({v, 0});
}

std::vector<double*> ReactionSet::variables() {
  // The order of the columns: concentrations, sum_<s> and mean_<s>, properties, measure, x, y, z, t.
  std::vector<double*> out;
  for (double& v : conc_) out.push_back(&v);
  for (double& v : neighbourhood_) out.push_back(&v);
  for (double& v : props_) out.push_back(&v);
  for (double* v : {&measure_, &x_, &y_, &z_, &t_}) out.push_back(v);
  return out;
}

ReactionSet::~ReactionSet() = default;

bool ReactionSet::usesAnyNeighbourhood() const {
  for (std::size_t s = 0; s < uses_sum_.size(); ++s)
    if (usesNeighbourhood(s)) return true;
  return false;
}

void ReactionSet::set(double t, double measure, const Vec3& centroid, std::span<const double> properties,
                      std::span<const double> conc, std::span<const double> neighbourhood) {
  for (std::size_t v = 0; v < conc_.size(); ++v) conc_[v] = conc[v];
  for (std::size_t v = 0; v < neighbourhood_.size(); ++v)
    neighbourhood_[v] = neighbourhood.empty() ? 0.0 : neighbourhood[v];
  for (std::size_t v = 0; v < props_.size(); ++v) props_[v] = properties[v];
  t_ = t;
  measure_ = measure;
  x_ = centroid.x();
  y_ = centroid.y();
  z_ = centroid.z();
}

void ReactionSet::notFinite(std::size_t s, std::size_t cell, double r) const {
  std::ostringstream msg;
  msg << "network: reaction of species '" << species_[s] << "', \"" << expressions_[s] << "\", gave " << r
      << " in cell " << cell << " at t = " << t_ << " with";
  for (std::size_t v = 0; v < species_.size(); ++v) msg << (v ? ", " : " ") << species_[v] << " = " << conc_[v];
  throw InputError(msg.str());
}

double ReactionSet::evaluateOne(std::size_t k) const {
  const detail::BatchExpression& batch = *batch_[k];
  if (!batch.supported()) return parsers_[k]->Eval();
  double r = 0.0;
  batch.evaluate(work_->members, 0, 1, &r);
  return r;
}

double ReactionSet::rate(std::size_t s, std::size_t cell) const {
  const int k = parser_of_[s];
  if (k < 0) return 0.0;
  const double r = evaluateOne(static_cast<std::size_t>(k));
  if (!std::isfinite(r)) notFinite(s, cell, r);
  return r;
}

void ReactionSet::setCell(const CellValues& values, std::size_t c) {
  const std::size_t S = species_.size();
  for (std::size_t v = 0; v < S; ++v) conc_[v] = values.conc[c * S + v];
  for (std::size_t v = 0; v < 2 * S; ++v)
    neighbourhood_[v] = values.neighbourhood ? values.neighbourhood[c * 2 * S + v] : 0.0;
  for (std::size_t v = 0; v < props_.size(); ++v) props_[v] = values.properties[v][c];
  t_ = values.t;
  measure_ = values.measure[c];
  x_ = values.centroid[c].x();
  y_ = values.centroid[c].y();
  z_ = values.centroid[c].z();
}

void ReactionSet::cellColumns(const CellValues& values, std::size_t first) {
  const std::size_t S = species_.size(), P = props_.size();
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "the centroids' coordinates are read with stride 3");
  static constexpr double zero = 0.0;
  using Column = detail::BatchExpression::Column;
  // The columns in the order of variables().
  std::vector<Column>& columns = work_->columns;
  columns.clear();
  for (std::size_t v = 0; v < S; ++v) columns.push_back({values.conc + first * S + v, S});
  for (std::size_t v = 0; v < 2 * S; ++v)
    columns.push_back(values.neighbourhood ? Column{values.neighbourhood + first * 2 * S + v, 2 * S}
                                           : Column{&zero, 0});
  for (std::size_t v = 0; v < P; ++v) columns.push_back({values.properties[v] + first, 1});
  columns.push_back({values.measure + first, 1});
  for (std::size_t d = 0; d < 3; ++d) columns.push_back({values.centroid[first].data() + d, 3});
  columns.push_back({&values.t, 0});
}

void ReactionSet::evaluateCells(const CellValues& values, std::size_t first, std::size_t count, double* rate) {
  const std::size_t S = species_.size();
  cellColumns(values, first);
  const std::vector<detail::BatchExpression::Column>& columns = work_->columns;
  for (std::size_t s = 0; s < S; ++s)
    if (parser_of_[s] < 0)
      for (std::size_t c = first; c < first + count; ++c) rate[c * S + s] = 0.0;
  for (std::size_t k = 0; k < parsers_.size(); ++k) {
    const std::size_t s = target_[k];
    if (!batch_[k]->supported()) {  // cell by cell through muparser
      for (std::size_t c = first; c < first + count; ++c) {
        setCell(values, c);
        rate[c * S + s] = parsers_[k]->Eval();
      }
      continue;
    }
    for (std::size_t b = first; b < first + count; b += detail::BatchExpression::kBlock) {
      const std::size_t m = std::min(detail::BatchExpression::kBlock, first + count - b);
      batch_[k]->evaluate(columns, b - first, m, work_->block.data());
      for (std::size_t i = 0; i < m; ++i) rate[(b + i) * S + s] = work_->block[i];
    }
  }
  // The first rate that is not finite, by cell then species as evaluate() would meet it.
  for (std::size_t c = first; c < first + count; ++c)
    for (std::size_t k = 0; k < parsers_.size(); ++k)
      if (const double r = rate[c * S + target_[k]]; !std::isfinite(r)) {
        setCell(values, c);
        notFinite(target_[k], c, r);
      }
}

bool ReactionSet::differenceCells(const CellValues& values, std::size_t first, std::size_t count, double root,
                                  const std::size_t* position, double* value) {
  constexpr std::size_t B = detail::BatchExpression::kBlock;
  const std::size_t S = species_.size();
  double h[B], shifted[B], up[B], down[B];
  bool finite = true;
  for (std::size_t b = first; b < first + count; b += B) {
    const std::size_t m = std::min(B, first + count - b);
    cellColumns(values, b);
    for (std::size_t q = 0; q < S; ++q) {
      const double* cq = values.conc + b * S + q;
      for (std::size_t i = 0; i < m; ++i) h[i] = root * std::max(std::abs(cq[i * S]), 1.0);
      const detail::BatchExpression::Column kept = work_->columns[q];
      work_->columns[q] = {shifted, 1};
      for (std::size_t s = 0; s < S; ++s) {
        if (!reads(s, q)) continue;
        const auto k = static_cast<std::size_t>(parser_of_[s]);
        const bool batch = batch_[k]->supported();
        for (int side = 0; side < 2; ++side) {
          double* out = side == 0 ? up : down;
          for (std::size_t i = 0; i < m; ++i) shifted[i] = side == 0 ? cq[i * S] + h[i] : cq[i * S] - h[i];
          if (batch) {
            batch_[k]->evaluate(work_->columns, 0, m, out);
          } else {
            for (std::size_t i = 0; i < m; ++i) {
              setCell(values, b + i);
              conc_[q] = shifted[i];
              out[i] = parsers_[k]->Eval();
            }
          }
        }
        for (std::size_t i = 0; i < m; ++i) {
          if (!std::isfinite(up[i]) || !std::isfinite(down[i])) {
            finite = false;
            continue;
          }
          value[position[(b + i) * S + s] + q] += (up[i] - down[i]) / (2 * h[i]);
        }
      }
      work_->columns[q] = kept;
    }
  }
  return finite;
}

void ReactionSet::evaluate(double t, std::size_t cell, double measure, const Vec3& centroid,
                           std::span<const double> properties, std::span<const double> conc, std::span<double> rate,
                           std::span<const double> neighbourhood) {
  set(t, measure, centroid, properties, conc, neighbourhood);
  for (std::size_t s = 0; s < rate.size(); ++s) rate[s] = 0.0;
  for (std::size_t k = 0; k < parsers_.size(); ++k) {
    const double r = evaluateOne(k);
    if (!std::isfinite(r)) notFinite(target_[k], cell, r);
    rate[target_[k]] = r;
  }
}

}  // namespace tessella::networks
