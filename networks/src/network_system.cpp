// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/network_system.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include "tessella/networks/pin_expression.hpp"
#include "tessella/networks/reaction_set.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::networks {

double CsrMatrix::at(std::size_t r, std::size_t c) const {
  const auto first = column.begin() + static_cast<std::ptrdiff_t>(row_start[r]);
  const auto last = column.begin() + static_cast<std::ptrdiff_t>(row_start[r + 1]);
  const auto it = std::lower_bound(first, last, c);
  return it != last && *it == c ? value[static_cast<std::size_t>(it - column.begin())] : 0.0;
}

namespace {
int other(const NetworkInterface& f, std::size_t c) { return f.cell_i == static_cast<int>(c) ? f.cell_j : f.cell_i; }
std::size_t otherCell(const NetworkInterface& f, std::size_t c) { return static_cast<std::size_t>(other(f, c)); }

// From this many cells on, the loops over cells are split over OpenMP threads.
constexpr std::size_t kParallelCells = 4096;

// body(first, count, thread) for the blocks of `block` cells (the last one shorter) over OpenMP threads; the
// blocks do not depend on the number of threads. An exception of the body is rethrown after the loop: the one of
// the lowest block.
template <class Body>
void forEachBlockOf(std::size_t block, std::size_t n, std::size_t threads, Body body) {
  std::exception_ptr failure;
  std::size_t failed = n;
  const int team = static_cast<int>(threads);
  const auto blocks = static_cast<std::ptrdiff_t>((n + block - 1) / block);
#pragma omp parallel for schedule(static) if (team > 1 && n >= kParallelCells) num_threads(team)
  for (std::ptrdiff_t b = 0; b < blocks; ++b) {
    const std::size_t first = static_cast<std::size_t>(b) * block;
    try {
      body(first, std::min(block, n - first), static_cast<std::size_t>(omp_get_thread_num()));
    } catch (...) {
#pragma omp critical(tessella_network_blocks)
      if (first < failed) {
        failed = first;
        failure = std::current_exception();
      }
    }
  }
  if (failure) std::rethrow_exception(failure);
}

// body(c, thread) for every cell c < n, over OpenMP threads (each cell's work only writes that cell's
// entries, so the results do not depend on the number of threads). An exception of the body is rethrown
// after the loop: the one of the lowest cell, whatever the number of threads.
template <class Body>
void forEachCell(std::size_t n, std::size_t threads, Body body) {
  forEachBlockOf(1, n, threads, [&](std::size_t c, std::size_t, std::size_t thread) { body(c, thread); });
}

// The reactions run over blocks of kReactionBlock cells.
constexpr std::size_t kReactionBlock = 256;
template <class Body>
void forEachBlock(std::size_t n, std::size_t threads, Body body) {
  forEachBlockOf(kReactionBlock, n, threads, body);
}

// J(r, c) += v on a fixed pattern.
void addAt(CsrMatrix& J, std::size_t r, std::size_t c, double v) {
  const auto first = J.column.begin() + static_cast<std::ptrdiff_t>(J.row_start[r]);
  const auto last = J.column.begin() + static_cast<std::ptrdiff_t>(J.row_start[r + 1]);
  const auto it = std::lower_bound(first, last, c);
  if (it == last || *it != c) throw std::logic_error("network Jacobian: entry outside the pattern");
  J.value[static_cast<std::size_t>(it - J.column.begin())] += v;
}
}  // namespace

const EnumTable<JacobianKind>& jacobianKinds() {
  static const EnumTable<JacobianKind> table(
      "Jacobian", {{"exact", JacobianKind::Exact, "The exact derivative dF/dy."},
                   {"neighbours", JacobianKind::Neighbours,
                    "dF/dy without the second-neighbour terms of PIN transport: sparser, an approximation "
                    "for the Newton iteration (conserves amounts all the same)."}});
  return table;
}

NetworkSystem::NetworkSystem(NetworkModel model, NetworkGraph graph, JacobianKind jacobian)
    : model_(std::move(model)), graph_(std::move(graph)), jacobian_kind_(jacobian) {
  model_.validate();
  graph_.validate();
  for (const std::string& p : model_.cell_properties)
    if (!graph_.properties.count(p))
      throw InputError("network: the cell property '" + p + "' the reactions read is not in the graph");
  reactions_.push_back(std::make_unique<ReactionSet>(model_));
  property_values_.assign(1, std::vector<double>(model_.cell_properties.size(), 0.0));
  if (model_.pin.enabled() && model_.pin.function == PinFunction::Exponential) log_base_ = std::log(model_.pin.base);
  pin_species_ = model_.pin.enabled() ? model_.speciesIndex(model_.pin.species) : -1;
  const bool dynamic = model_.pin.dynamic();
  if (dynamic && model_.pin.model == PinModel::Expression) pin_expression_ = std::make_unique<PinExpression>(model_);
  pin_cell_coupled_ =
      dynamic && (model_.pin.model == PinModel::Expression ? pin_expression_->usesPinCell() : model_.pin.bounded);
  const std::size_t n = numCells(), S = numSpecies();
  neighbours_.assign(n, {});
  for (std::size_t f = 0; f < graph_.interfaces.size(); ++f) {
    neighbours_[static_cast<std::size_t>(graph_.interfaces[f].cell_i)].push_back(f);
    neighbours_[static_cast<std::size_t>(graph_.interfaces[f].cell_j)].push_back(f);
  }
  // The neighbours as flat arrays (the loops over cells read them at every right-hand side).
  adjacent_start_.assign(n + 1, 0);
  for (std::size_t c = 0; c < n; ++c) {
    for (std::size_t f : neighbours_[c]) adjacent_cell_.push_back(otherCell(graph_.interfaces[f], c));
    adjacent_start_[c + 1] = adjacent_cell_.size();
  }
  // The pattern, row by row.
  pattern_.rows = size();
  pattern_.row_start.assign(size() + 1, 0);
  std::vector<std::size_t> cols;
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t s = 0; s < S; ++s) {
      cols.clear();
      if (reactions_[0]->empty())
        cols.push_back(index(c, s));
      else
        for (std::size_t q = 0; q < S; ++q) cols.push_back(index(c, q));
      // Neighbourhood terms: a reaction reading sum_q / mean_q depends on q in every neighbour.
      for (std::size_t q = 0; q < S; ++q)
        if (reactions_[0]->usesNeighbourhood(q))
          for (std::size_t f : neighbours_[c]) cols.push_back(index(otherCell(graph_.interfaces[f], c), q));
      const bool passive = model_.species[s].permeability > 0;
      const bool pinned = static_cast<int>(s) == pin_species_;
      if (passive || pinned)
        for (std::size_t f : neighbours_[c]) {
          const auto j = static_cast<std::size_t>(other(graph_.interfaces[f], c));
          cols.push_back(index(j, s));
          if (pinned && dynamic) {
            cols.push_back(pinIndex(f, 0));
            cols.push_back(pinIndex(f, 1));
          } else if (pinned && jacobian_kind_ == JacobianKind::Exact) {
            for (std::size_t g : neighbours_[j]) cols.push_back(index(otherCell(graph_.interfaces[g], j), s));
          }
        }
      std::sort(cols.begin(), cols.end());
      cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
      pattern_.column.insert(pattern_.column.end(), cols.begin(), cols.end());
      pattern_.row_start[index(c, s) + 1] = pattern_.column.size();
    }
  // Dynamic PIN: the density on cell o's side of interface k reads both cells' amounts, both sides' densities
  // and, when coupled, every density on o's side of its interfaces.
  for (std::size_t k = 0; k < numPinStates() / 2; ++k)
    for (int side = 0; side < 2; ++side) {
      const NetworkInterface& f = graph_.interfaces[k];
      const auto o = static_cast<std::size_t>(side == 0 ? f.cell_i : f.cell_j);
      const auto a = static_cast<std::size_t>(pin_species_);
      cols = {index(static_cast<std::size_t>(f.cell_i), a), index(static_cast<std::size_t>(f.cell_j), a),
              pinIndex(k, 0), pinIndex(k, 1)};
      if (pin_cell_coupled_)
        for (std::size_t g : neighbours_[o])
          cols.push_back(pinIndex(g, graph_.interfaces[g].cell_i == static_cast<int>(o) ? 0 : 1));
      std::sort(cols.begin(), cols.end());
      cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
      pattern_.column.insert(pattern_.column.end(), cols.begin(), cols.end());
      pattern_.row_start[pinIndex(k, side) + 1] = pattern_.column.size();
    }
  pattern_.value.assign(pattern_.column.size(), 0.0);
  if (!reactions_[0]->empty())
    for (std::size_t c = 0; c < n; ++c)
      for (std::size_t s = 0; s < S; ++s) {
        const auto row = pattern_.column.begin() + static_cast<std::ptrdiff_t>(pattern_.row_start[index(c, s)]);
        const auto end = pattern_.column.begin() + static_cast<std::ptrdiff_t>(pattern_.row_start[index(c, s) + 1]);
        const auto own = std::lower_bound(row, end, index(c, 0));
        reaction_entry_.push_back(static_cast<std::size_t>(own - pattern_.column.begin()));
      }
  pin_denominator_.assign(n, 0.0);
  pin_weight_.assign(n, 0.0);
  pin_weight_derivative_.assign(n, 0.0);
  pin_out_.assign(n, 0.0);
  conc_.assign(n * S, 0.0);
  neighbourhood_.assign(reactions_[0]->usesAnyNeighbourhood() ? n * 2 * S : 0, 0.0);
  pin_cell_.assign(n, 0.0);
  for (const NetworkSpecies& species : model_.species) permeability_.push_back(species.permeability);
  readMeasures();
}

void NetworkSystem::readMeasures() {
  property_columns_.clear();
  for (const std::string& name : model_.cell_properties) property_columns_.push_back(&graph_.properties.at(name));
  adjacent_measure_.resize(adjacent_cell_.size());
  for (std::size_t c = 0; c < numCells(); ++c) {
    std::size_t a = adjacent_start_[c];
    for (std::size_t f : neighbours_[c]) adjacent_measure_[a++] = graph_.interfaces[f].measure;
  }
  wall_total_.assign(numCells(), 0.0);
  for (const NetworkInterface& f : graph_.interfaces) {
    wall_total_[static_cast<std::size_t>(f.cell_i)] += f.measure;
    wall_total_[static_cast<std::size_t>(f.cell_j)] += f.measure;
  }
}

std::string NetworkSystem::structureDifference(const NetworkGraph& graph) const {
  if (graph.numCells() != numCells() || graph.interfaces.size() != graph_.interfaces.size())
    return "the new graph has " + std::to_string(graph.numCells()) + " cells and " +
           std::to_string(graph.interfaces.size()) + " interfaces, the system " + std::to_string(numCells()) +
           " and " + std::to_string(graph_.interfaces.size());
  for (std::size_t k = 0; k < graph.interfaces.size(); ++k) {
    const NetworkInterface &a = graph.interfaces[k], &b = graph_.interfaces[k];
    if (a.cell_i != b.cell_i || a.cell_j != b.cell_j)
      return "interface " + std::to_string(k) + " joins cells " + std::to_string(a.cell_i) + " and " +
             std::to_string(a.cell_j) + ", in the system " + std::to_string(b.cell_i) + " and " +
             std::to_string(b.cell_j);
  }
  for (const std::string& p : model_.cell_properties) {
    const auto it = graph.properties.find(p);
    if (it == graph.properties.end()) return "the cell property '" + p + "' the reactions read is not in the graph";
    if (it->second.size() != numCells())
      return "the cell property '" + p + "' has " + std::to_string(it->second.size()) + " values for " +
             std::to_string(numCells()) + " cells";
  }
  return {};
}

bool NetworkSystem::sameStructure(const NetworkGraph& graph) const { return structureDifference(graph).empty(); }

void NetworkSystem::updateGraph(NetworkGraph graph) {
  graph.validate();
  if (const std::string difference = structureDifference(graph); !difference.empty())
    throw InputError("network: updateGraph: " + difference);
  graph_ = std::move(graph);
  readMeasures();
}

NetworkSystem::~NetworkSystem() = default;

void NetworkSystem::setThreads(std::size_t threads) {
  threads_ = threads == 0 ? static_cast<std::size_t>(std::max(omp_get_max_threads(), 1)) : threads;
}

void NetworkSystem::prepareThreads() {
  const std::size_t threads = threads_;
  while (reactions_.size() < threads) reactions_.push_back(std::make_unique<ReactionSet>(model_));
  property_values_.resize(std::max(property_values_.size(), threads), std::vector<double>(property_columns_.size()));
}

double NetworkSystem::pinWeight(double c) const {
  return model_.pin.function == PinFunction::Exponential ? std::exp(log_base_ * c) : model_.pin.weight(c);
}

double NetworkSystem::pinWeightDerivative(double c) const {
  return model_.pin.function == PinFunction::Exponential ? log_base_ * std::exp(log_base_ * c)
                                                         : model_.pin.weightDerivative(c);
}

CellValues NetworkSystem::cellValues(double t) const {
  CellValues values;
  values.t = t;
  values.conc = conc_.data();
  values.neighbourhood = neighbourhood_.empty() ? nullptr : neighbourhood_.data();
  values.measure = graph_.measure.data();
  values.centroid = graph_.centroid.data();
  for (const std::vector<double>* column : property_columns_) values.properties.push_back(column->data());
  return values;
}

void NetworkSystem::neighbourhoodTerms() {
  if (neighbourhood_.empty()) return;
  const std::size_t S = numSpecies();
  forEachCell(numCells(), threads_, [&](std::size_t c, std::size_t) {
    double* terms = &neighbourhood_[c * 2 * S];
    std::fill(terms, terms + 2 * S, 0.0);
    for (std::size_t a = adjacent_start_[c]; a < adjacent_start_[c + 1]; ++a)
      for (std::size_t s = 0; s < S; ++s) terms[s] += adjacent_measure_[a] * conc_[index(adjacent_cell_[a], s)];
    for (std::size_t s = 0; s < S; ++s) terms[S + s] = wall_total_[c] > 0 ? terms[s] / wall_total_[c] : 0.0;
  });
}

void NetworkSystem::rhs(double t, std::span<const double> y, std::span<double> ydot) {
  const std::size_t n = numCells(), S = numSpecies();
  prepareThreads();
  const bool reactions = !reactions_[0]->empty(), gradient = pin_species_ >= 0 && !model_.pin.dynamic();
  const auto p = static_cast<std::size_t>(std::max(pin_species_, 0));
  const PinTransport& pin = model_.pin;
  forEachCell(n, threads_, [&](std::size_t c, std::size_t) {
    for (std::size_t s = 0; s < S; ++s) conc_[index(c, s)] = y[index(c, s)] / graph_.measure[c];
    if (gradient) pin_weight_[c] = pinWeight(conc_[index(c, p)]);
  });
  if (reactions) neighbourhoodTerms();
  if (gradient) pinDenominators();  // and pin_out_
  // The reactions' rates, over blocks of cells (each reaction's bytecode runs on a whole block).
  if (reactions) {
    const CellValues values = cellValues(t);
    forEachBlock(n, threads_, [&](std::size_t first, std::size_t count, std::size_t thread) {
      reactions_[thread]->evaluateCells(values, first, count, ydot.data());
    });
  }
  // Cell by cell: its reactions (the amount changes at measure * rate), the passive exchange P L (c_i - c_j)
  // from i to each neighbour j, and the PIN efflux G(c_i) L_ij f(c_j) / D_i from i to j and from j to i. A flux between
  // two cells is computed the same way in both, so what one loses the other gains exactly.
  forEachCell(n, threads_, [&](std::size_t c, std::size_t) {
    std::span<double> rate(&ydot[index(c, 0)], S);
    if (reactions)
      for (std::size_t s = 0; s < S; ++s) rate[s] *= graph_.measure[c];
    else
      std::fill(rate.begin(), rate.end(), 0.0);
    // The sums run in local variables (the same additions in the same order as into rate[s]).
    const std::size_t first = adjacent_start_[c], last = adjacent_start_[c + 1];
    for (std::size_t s = 0; s < S; ++s) {
      const double P = permeability_[s];
      if (!(P > 0)) continue;
      const double own = conc_[index(c, s)];
      double r = rate[s];
      for (std::size_t a = first; a < last; ++a)
        r -= P * adjacent_measure_[a] * (own - conc_[index(adjacent_cell_[a], s)]);
      rate[s] = r;
    }
    if (gradient) {
      const double out = pin_out_[c], weight = pin_weight_[c];
      double r = rate[p];
      for (std::size_t a = first; a < last; ++a) {
        const std::size_t j = adjacent_cell_[a];
        r -= out * adjacent_measure_[a] * pin_weight_[j];
        r += pin_out_[j] * adjacent_measure_[a] * weight;
      }
      rate[p] = r;
    }
  });
  if (model_.pin.dynamic()) {
    // PIN as a state: T L_ij (p_ij c_i - p_ji c_j) from i to j, and the densities' rates.
    const auto a = static_cast<std::size_t>(pin_species_);
    const double T = pin.rate;
    for (std::size_t k = 0; k < graph_.interfaces.size(); ++k) {
      const NetworkInterface& f = graph_.interfaces[k];
      const auto i = static_cast<std::size_t>(f.cell_i), j = static_cast<std::size_t>(f.cell_j);
      const double J =
          T * f.measure * (y[pinIndex(k, 0)] * conc_[index(i, a)] - y[pinIndex(k, 1)] * conc_[index(j, a)]);
      ydot[index(i, a)] -= J;
      ydot[index(j, a)] += J;
    }
    pinCellAmounts(y);
    for (std::size_t k = 0; k < graph_.interfaces.size(); ++k)
      for (int side = 0; side < 2; ++side) ydot[pinIndex(k, side)] = pinRate(t, k, side, y, nullptr);
  }
}

void NetworkSystem::pinDenominators() {
  const auto p = static_cast<std::size_t>(pin_species_);
  forEachCell(numCells(), threads_, [&](std::size_t c, std::size_t) {
    double d = model_.pin.saturation;
    for (std::size_t a = adjacent_start_[c]; a < adjacent_start_[c + 1]; ++a)
      d += adjacent_measure_[a] * pin_weight_[adjacent_cell_[a]];
    pin_denominator_[c] = d;
    // G(c_i) / D_i: the efflux T P(c_i) g(c_i) shared out over the walls.
    pin_out_[c] = d > 0 ? model_.pin.effluxFactor(conc_[index(c, p)]) / d : 0.0;
  });
}

void NetworkSystem::pinCellAmounts(std::span<const double> y) {
  std::fill(pin_cell_.begin(), pin_cell_.end(), 0.0);
  for (std::size_t k = 0; k < graph_.interfaces.size(); ++k) {
    const NetworkInterface& f = graph_.interfaces[k];
    pin_cell_[static_cast<std::size_t>(f.cell_i)] += f.measure * y[pinIndex(k, 0)];
    pin_cell_[static_cast<std::size_t>(f.cell_j)] += f.measure * y[pinIndex(k, 1)];
  }
}

double NetworkSystem::pinRate(double t, std::size_t k, int side, std::span<const double> y,
                              std::array<double, 8>* partial) {
  using E = PinExpression;
  const NetworkInterface& f = graph_.interfaces[k];
  const auto o = static_cast<std::size_t>(side == 0 ? f.cell_i : f.cell_j);
  const auto q = static_cast<std::size_t>(side == 0 ? f.cell_j : f.cell_i);
  const auto a = static_cast<std::size_t>(pin_species_);
  const PinTransport& pin = model_.pin;
  E::Arguments v{};
  v[E::kCi] = conc_[index(o, a)];
  v[E::kCj] = conc_[index(q, a)];
  v[E::kPin] = y[pinIndex(k, side)];
  v[E::kPinOpposite] = y[pinIndex(k, 1 - side)];
  v[E::kFlux] = pin.rate * (v[E::kPin] * v[E::kCi] - v[E::kPinOpposite] * v[E::kCj]) +
                model_.species[a].permeability * (v[E::kCi] - v[E::kCj]);
  v[E::kWall] = f.measure;
  v[E::kMeasure] = graph_.measure[o];
  v[E::kPinCell] = pin_cell_[o];
  if (pin_expression_) {
    if (partial) *partial = pin_expression_->derivatives(t, v, o, q);
    return pin_expression_->evaluate(t, v, o, q);
  }
  // with_the_flux: (basal + production h(phi)) B - decay p.
  const double B = pin.bounded ? 1.0 - v[E::kPinCell] / pin.total : 1.0;
  const double made = pin.basal + pin.production * pin.fluxResponse(v[E::kFlux]);
  if (partial) {
    partial->fill(0.0);
    (*partial)[E::kPin] = -pin.decay;
    (*partial)[E::kFlux] = pin.production * pin.fluxResponseDerivative(v[E::kFlux]) * B;
    if (pin.bounded) (*partial)[E::kPinCell] = -made / pin.total;
  }
  return made * B - pin.decay * v[E::kPin];
}

bool NetworkSystem::inPattern(std::size_t r, std::size_t c) const {
  return std::binary_search(pattern_.column.begin() + static_cast<std::ptrdiff_t>(pattern_.row_start[r]),
                            pattern_.column.begin() + static_cast<std::ptrdiff_t>(pattern_.row_start[r + 1]), c);
}

void NetworkSystem::jacobian(double t, std::span<const double> y, CsrMatrix& J) {
  if (J.column.size() != pattern_.column.size()) J = pattern_;
  std::fill(J.value.begin(), J.value.end(), 0.0);
  const std::size_t n = numCells(), S = numSpecies();
  prepareThreads();
  forEachCell(n, threads_, [&](std::size_t c, std::size_t) {
    for (std::size_t s = 0; s < S; ++s) conc_[index(c, s)] = y[index(c, s)] / graph_.measure[c];
  });
  // Reactions: d(V r_s)/dy_q = dr_s/dc_q, by central differences in the cell's concentrations; cell by cell
  // (a cell's reactions only write its rows).
  if (!reactions_[0]->empty()) {
    neighbourhoodTerms();
    const double root = std::cbrt(std::numeric_limits<double>::epsilon());
    // Only the reactions that read the perturbed value are evaluated (the others' differences are zero).
    // Cell c's differences one by one: in its own concentrations when `own`, and in its neighbourhood terms.
    auto cellByCell = [&](std::size_t c, std::size_t thread, bool own) {
      ReactionSet& reactions = *reactions_[thread];
      std::vector<double>& properties = property_values_[thread];
      for (std::size_t k = 0; k < property_columns_.size(); ++k) properties[k] = (*property_columns_[k])[c];
      const std::span<const double> cc(&conc_[index(c, 0)], S);
      std::span<const double> nb;
      if (!neighbourhood_.empty()) nb = std::span<const double>(&neighbourhood_[c * 2 * S], 2 * S);
      reactions.set(t, graph_.measure[c], graph_.centroid[c], properties, cc, nb);
      for (std::size_t q = 0; q < S && own; ++q) {
        const double h = root * std::max(std::abs(cc[q]), 1.0);
        for (std::size_t s = 0; s < S; ++s) {
          if (!reactions.reads(s, q)) continue;
          reactions.setConcentration(q, cc[q] + h);
          const double up = reactions.rate(s, c);
          reactions.setConcentration(q, cc[q] - h);
          const double down = reactions.rate(s, c);
          reactions.setConcentration(q, cc[q]);
          addAt(J, index(c, s), index(c, q), (up - down) / (2 * h));
        }
      }
      // Neighbourhood terms: d(V_c r_s)/dy_jq = V_c (dr_s/dsum_q + dr_s/dmean_q / W_c) L_cj / V_j,
      // W_c = sum_j L_cj, the partial derivatives by central differences in sum_q and mean_q.
      if (nb.empty()) return;
      thread_local std::vector<double> derivative;  // dr_s/dsum_q, then dr_s/dmean_q
      derivative.assign(2 * S, 0.0);
      for (std::size_t q = 0; q < S; ++q) {
        if (!reactions_[0]->usesNeighbourhood(q)) continue;
        for (std::size_t which = 0; which < 2; ++which) {
          const double keep = nb[which * S + q];
          const double h = root * std::max(std::abs(keep), 1.0);
          for (std::size_t s = 0; s < S; ++s) {
            derivative[which * S + s] = 0.0;
            if (!reactions.readsNeighbourhood(s, which, q)) continue;
            reactions.setNeighbourhood(which, q, keep + h);
            const double up = reactions.rate(s, c);
            reactions.setNeighbourhood(which, q, keep - h);
            const double down = reactions.rate(s, c);
            reactions.setNeighbourhood(which, q, keep);
            derivative[which * S + s] = (up - down) / (2 * h);
          }
        }
        const double* dsum = &derivative[0];
        const double* dmean = &derivative[S];
        for (std::size_t f : neighbours_[c]) {
          const std::size_t j = otherCell(graph_.interfaces[f], c);
          const double L = graph_.interfaces[f].measure;
          for (std::size_t s = 0; s < S; ++s) {
            const double per_c = dsum[s] + (wall_total_[c] > 0 ? dmean[s] / wall_total_[c] : 0.0);
            addAt(J, index(c, s), index(j, q), graph_.measure[c] * per_c * L / graph_.measure[j]);
          }
        }
      }
    };
    // Over blocks of cells: the differences in the cells' own concentrations with each reaction's bytecode on the
    // whole block (the same values as cell by cell), into the cached positions; then the neighbourhood terms' cell
    // by cell. A rate that is not finite: the block again cell by cell, for the error cell by cell gives.
    const CellValues values = cellValues(t);
    forEachBlock(n, threads_, [&](std::size_t first, std::size_t count, std::size_t thread) {
      if (!reactions_[thread]->differenceCells(values, first, count, root, reaction_entry_.data(), J.value.data())) {
        for (std::size_t c = first; c < first + count; ++c) cellByCell(c, thread, true);
        throw std::logic_error("network Jacobian: a rate not finite over a block of cells but finite cell by cell");
      }
      if (!neighbourhood_.empty())
        for (std::size_t c = first; c < first + count; ++c) cellByCell(c, thread, false);
    });
  }
  for (std::size_t s = 0; s < S; ++s) {
    const double P = model_.species[s].permeability;
    if (!(P > 0)) continue;
    for (const NetworkInterface& f : graph_.interfaces) {
      const auto i = static_cast<std::size_t>(f.cell_i), j = static_cast<std::size_t>(f.cell_j);
      const double di = P * f.measure / graph_.measure[i], dj = -P * f.measure / graph_.measure[j];
      addAt(J, index(i, s), index(i, s), -di);
      addAt(J, index(j, s), index(i, s), di);
      addAt(J, index(i, s), index(j, s), -dj);
      addAt(J, index(j, s), index(j, s), dj);
    }
  }
  if (model_.pin.dynamic()) {
    using E = PinExpression;
    const auto a = static_cast<std::size_t>(pin_species_);
    const double T = model_.pin.rate, P = model_.species[a].permeability;
    for (std::size_t k = 0; k < graph_.interfaces.size(); ++k) {
      const NetworkInterface& f = graph_.interfaces[k];
      const auto i = static_cast<std::size_t>(f.cell_i), j = static_cast<std::size_t>(f.cell_j);
      const double TL = T * f.measure;
      // J = T L (p_ij c_i - p_ji c_j), taken from i and given to j.
      auto add = [&](std::size_t col, double dJ) {
        addAt(J, index(i, a), col, -dJ);
        addAt(J, index(j, a), col, dJ);
      };
      add(index(i, a), TL * y[pinIndex(k, 0)] / graph_.measure[i]);
      add(index(j, a), -TL * y[pinIndex(k, 1)] / graph_.measure[j]);
      add(pinIndex(k, 0), TL * conc_[index(i, a)]);
      add(pinIndex(k, 1), -TL * conc_[index(j, a)]);
    }
    pinCellAmounts(y);
    std::array<double, 8> d{};
    for (std::size_t k = 0; k < graph_.interfaces.size(); ++k)
      for (int side = 0; side < 2; ++side) {
        const NetworkInterface& f = graph_.interfaces[k];
        const auto o = static_cast<std::size_t>(side == 0 ? f.cell_i : f.cell_j);
        const auto q = static_cast<std::size_t>(side == 0 ? f.cell_j : f.cell_i);
        pinRate(t, k, side, y, &d);
        const std::size_t r = pinIndex(k, side);
        const double p_own = y[pinIndex(k, side)], p_opp = y[pinIndex(k, 1 - side)];
        const double c_o = conc_[index(o, a)], c_q = conc_[index(q, a)];
        // phi = T (p_own c_o - p_opp c_q) + P (c_o - c_q).
        addAt(J, r, index(o, a), (d[E::kCi] + d[E::kFlux] * (T * p_own + P)) / graph_.measure[o]);
        addAt(J, r, index(q, a), (d[E::kCj] - d[E::kFlux] * (T * p_opp + P)) / graph_.measure[q]);
        addAt(J, r, pinIndex(k, side), d[E::kPin] + d[E::kFlux] * T * c_o);
        addAt(J, r, pinIndex(k, 1 - side), d[E::kPinOpposite] - d[E::kFlux] * T * c_q);
        if (pin_cell_coupled_)
          for (std::size_t g : neighbours_[o]) {
            const NetworkInterface& h = graph_.interfaces[g];
            addAt(J, r, pinIndex(g, h.cell_i == static_cast<int>(o) ? 0 : 1), d[E::kPinCell] * h.measure);
          }
      }
  } else if (pin_species_ >= 0) {
    const auto p = static_cast<std::size_t>(pin_species_);
    const PinTransport& pin = model_.pin;
    for (std::size_t c = 0; c < n; ++c) {
      pin_weight_[c] = pinWeight(conc_[index(c, p)]);
      pin_weight_derivative_[c] = pinWeightDerivative(conc_[index(c, p)]);
    }
    pinDenominators();
    for (std::size_t i = 0; i < n; ++i) {
      const double D = pin_denominator_[i];
      if (!(D > 0)) continue;
      const double ci = conc_[index(i, p)], G = pin.effluxFactor(ci), dG = pin.effluxFactorDerivative(ci);
      for (std::size_t f : neighbours_[i]) {
        const auto j = static_cast<std::size_t>(other(graph_.interfaces[f], i));
        const double L = graph_.interfaces[f].measure;
        const std::size_t ri = index(i, p), rj = index(j, p);
        // J_ij = G(c_i) L w_j / D_i, G(c) = T P(c) g(c).
        auto add = [&](std::size_t m, double dJ_dc_m) {
          const double d = dJ_dc_m / graph_.measure[m];
          addAt(J, ri, index(m, p), -d);
          addAt(J, rj, index(m, p), d);
        };
        add(i, dG * L * pin_weight_[j] / D);
        add(j, G * L * pin_weight_derivative_[j] / D);
        for (std::size_t g : neighbours_[i]) {
          const auto m = static_cast<std::size_t>(other(graph_.interfaces[g], i));
          // Neighbours: leave out the pair of entries when the receiver's row lacks m (a second neighbour).
          if (jacobian_kind_ == JacobianKind::Neighbours && !inPattern(rj, index(m, p))) continue;
          add(m, -G * L * pin_weight_[j] * graph_.interfaces[g].measure * pin_weight_derivative_[m] / (D * D));
        }
      }
    }
  }
}

std::vector<PinSides> NetworkSystem::pin(std::span<const double> y) const {
  std::vector<PinSides> out(graph_.interfaces.size());
  if (pin_species_ < 0) return out;
  if (model_.pin.dynamic()) {
    for (std::size_t k = 0; k < out.size(); ++k) {
      out[k].ij = graph_.interfaces[k].measure * y[pinIndex(k, 0)];
      out[k].ji = graph_.interfaces[k].measure * y[pinIndex(k, 1)];
    }
    return out;
  }
  const auto p = static_cast<std::size_t>(pin_species_);
  const PinTransport& pin = model_.pin;
  const std::size_t n = numCells();
  std::vector<double> w(n), D(n, pin.saturation);
  for (std::size_t c = 0; c < n; ++c) w[c] = pinWeight(y[index(c, p)] / graph_.measure[c]);
  for (const NetworkInterface& f : graph_.interfaces) {
    D[static_cast<std::size_t>(f.cell_i)] += f.measure * w[static_cast<std::size_t>(f.cell_j)];
    D[static_cast<std::size_t>(f.cell_j)] += f.measure * w[static_cast<std::size_t>(f.cell_i)];
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    const NetworkInterface& f = graph_.interfaces[k];
    const auto i = static_cast<std::size_t>(f.cell_i), j = static_cast<std::size_t>(f.cell_j);
    const double ci = y[index(i, p)] / graph_.measure[i], cj = y[index(j, p)] / graph_.measure[j];
    if (D[i] > 0) out[k].ij = pin.cellPin(ci) * f.measure * w[j] / D[i];
    if (D[j] > 0) out[k].ji = pin.cellPin(cj) * f.measure * w[i] / D[j];
  }
  return out;
}

std::vector<PinSides> NetworkSystem::pinDensity(std::span<const double> y) const {
  if (model_.pin.dynamic()) {
    std::vector<PinSides> out(graph_.interfaces.size());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = {y[pinIndex(k, 0)], y[pinIndex(k, 1)]};
    return out;
  }
  std::vector<PinSides> out = pin(y);
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double L = graph_.interfaces[k].measure;
    out[k] = L > 0 ? PinSides{out[k].ij / L, out[k].ji / L} : PinSides{};
  }
  return out;
}

std::vector<Vec3> NetworkSystem::polarity(std::span<const double> y) const {
  std::vector<Vec3> out(numCells(), Vec3::Zero());
  const std::vector<PinSides> sides = pin(y);
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const NetworkInterface& f = graph_.interfaces[k];
    out[static_cast<std::size_t>(f.cell_i)] += sides[k].ij * f.normal;
    out[static_cast<std::size_t>(f.cell_j)] -= sides[k].ji * f.normal;
  }
  return out;
}

double NetworkSystem::totalAmount(std::span<const double> y, std::size_t s) const {
  double sum = 0.0;
  for (std::size_t c = 0; c < numCells(); ++c) sum += y[index(c, s)];
  return sum;
}

}  // namespace tessella::networks
