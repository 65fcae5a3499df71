// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/network_system.hpp"

#include <algorithm>
#include <cmath>
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
  reactions_ = std::make_unique<ReactionSet>(model_);
  for (const std::string& name : model_.cell_properties) property_columns_.push_back(&graph_.properties.at(name));
  property_values_.assign(property_columns_.size(), 0.0);
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
  // The pattern, row by row.
  pattern_.rows = size();
  pattern_.row_start.assign(size() + 1, 0);
  std::vector<std::size_t> cols;
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t s = 0; s < S; ++s) {
      cols.clear();
      if (reactions_->empty())
        cols.push_back(index(c, s));
      else
        for (std::size_t q = 0; q < S; ++q) cols.push_back(index(c, q));
      // Neighbourhood terms: a reaction reading sum_q / mean_q depends on q in every neighbour.
      for (std::size_t q = 0; q < S; ++q)
        if (reactions_->usesNeighbourhood(q))
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
  pin_denominator_.assign(n, 0.0);
  pin_weight_.assign(n, 0.0);
  pin_weight_derivative_.assign(n, 0.0);
  conc_.assign(n * S, 0.0);
  neighbourhood_.assign(reactions_->usesAnyNeighbourhood() ? n * 2 * S : 0, 0.0);
  wall_total_.assign(n, 0.0);
  for (const NetworkInterface& f : graph_.interfaces) {
    wall_total_[static_cast<std::size_t>(f.cell_i)] += f.measure;
    wall_total_[static_cast<std::size_t>(f.cell_j)] += f.measure;
  }
  pin_cell_.assign(n, 0.0);
}

NetworkSystem::~NetworkSystem() = default;

void NetworkSystem::evaluateReactions(double t, std::size_t cell, std::span<const double> conc,
                                      std::span<double> rate, std::span<const double> neighbourhood) {
  for (std::size_t k = 0; k < property_columns_.size(); ++k) property_values_[k] = (*property_columns_[k])[cell];
  if (neighbourhood.empty() && !neighbourhood_.empty())
    neighbourhood = std::span<const double>(&neighbourhood_[cell * 2 * numSpecies()], 2 * numSpecies());
  reactions_->evaluate(t, cell, graph_.measure[cell], graph_.centroid[cell], property_values_, conc, rate,
                       neighbourhood);
}

void NetworkSystem::neighbourhoodTerms() {
  if (neighbourhood_.empty()) return;
  const std::size_t S = numSpecies();
  std::fill(neighbourhood_.begin(), neighbourhood_.end(), 0.0);
  for (const NetworkInterface& f : graph_.interfaces) {
    const auto i = static_cast<std::size_t>(f.cell_i), j = static_cast<std::size_t>(f.cell_j);
    for (std::size_t s = 0; s < S; ++s) {
      neighbourhood_[i * 2 * S + s] += f.measure * conc_[index(j, s)];
      neighbourhood_[j * 2 * S + s] += f.measure * conc_[index(i, s)];
    }
  }
  for (std::size_t c = 0; c < numCells(); ++c)
    for (std::size_t s = 0; s < S; ++s)
      neighbourhood_[c * 2 * S + S + s] = wall_total_[c] > 0 ? neighbourhood_[c * 2 * S + s] / wall_total_[c] : 0.0;
}

void NetworkSystem::rhs(double t, std::span<const double> y, std::span<double> ydot) {
  const std::size_t n = numCells(), S = numSpecies();
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t s = 0; s < S; ++s) conc_[index(c, s)] = y[index(c, s)] / graph_.measure[c];
  // Reactions: the amount changes at measure * rate.
  if (!reactions_->empty()) {
    neighbourhoodTerms();
    for (std::size_t c = 0; c < n; ++c) {
      std::span<const double> conc(&conc_[index(c, 0)], S);
      std::span<double> rate(&ydot[index(c, 0)], S);
      evaluateReactions(t, c, conc, rate);
      for (std::size_t s = 0; s < S; ++s) rate[s] *= graph_.measure[c];
    }
  } else {
    std::fill(ydot.begin(), ydot.end(), 0.0);
  }
  // Passive exchange: P L (c_i - c_j) from i to j.
  for (std::size_t s = 0; s < S; ++s) {
    const double P = model_.species[s].permeability;
    if (!(P > 0)) continue;
    for (const NetworkInterface& f : graph_.interfaces) {
      const auto i = static_cast<std::size_t>(f.cell_i), j = static_cast<std::size_t>(f.cell_j);
      const double J = P * f.measure * (conc_[index(i, s)] - conc_[index(j, s)]);
      ydot[index(i, s)] -= J;
      ydot[index(j, s)] += J;
    }
  }
  if (model_.pin.dynamic()) {
    // PIN as a state: T L_ij (p_ij c_i - p_ji c_j) from i to j, and the densities' rates.
    const auto a = static_cast<std::size_t>(pin_species_);
    const double T = model_.pin.rate;
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
    return;
  }
  // PIN efflux: T PIN_ij g(c_i) = G(c_i) L_ij f(c_j) / D_i from i to j, both directions of every interface.
  if (pin_species_ >= 0) {
    const auto p = static_cast<std::size_t>(pin_species_);
    const PinTransport& pin = model_.pin;
    for (std::size_t c = 0; c < n; ++c) pin_weight_[c] = pin.weight(conc_[index(c, p)]);
    pinDenominators();
    for (std::size_t c = 0; c < n; ++c) {
      if (!(pin_denominator_[c] > 0)) continue;
      const double out = pin.effluxFactor(conc_[index(c, p)]) / pin_denominator_[c];
      for (std::size_t f : neighbours_[c]) {
        const auto j = static_cast<std::size_t>(other(graph_.interfaces[f], c));
        const double J = out * graph_.interfaces[f].measure * pin_weight_[j];
        ydot[index(c, p)] -= J;
        ydot[index(j, p)] += J;
      }
    }
  }
}

void NetworkSystem::pinDenominators() {
  for (std::size_t c = 0; c < numCells(); ++c) {
    double d = model_.pin.saturation;
    for (std::size_t f : neighbours_[c])
      d += graph_.interfaces[f].measure * pin_weight_[otherCell(graph_.interfaces[f], c)];
    pin_denominator_[c] = d;
  }
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
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t s = 0; s < S; ++s) conc_[index(c, s)] = y[index(c, s)] / graph_.measure[c];
  // Reactions: d(V r_s)/dy_q = dr_s/dc_q, by central differences in the cell's concentrations.
  if (!reactions_->empty()) {
    neighbourhoodTerms();
    std::vector<double> cc(S), up(S), down(S);
    const double root = std::cbrt(std::numeric_limits<double>::epsilon());
    for (std::size_t c = 0; c < n; ++c) {
      for (std::size_t q = 0; q < S; ++q) cc[q] = conc_[index(c, q)];
      for (std::size_t q = 0; q < S; ++q) {
        const double h = root * std::max(std::abs(cc[q]), 1.0);
        const double keep = cc[q];
        cc[q] = keep + h;
        evaluateReactions(t, c, cc, up);
        cc[q] = keep - h;
        evaluateReactions(t, c, cc, down);
        cc[q] = keep;
        for (std::size_t s = 0; s < S; ++s) addAt(J, index(c, s), index(c, q), (up[s] - down[s]) / (2 * h));
      }
    }
    // Neighbourhood terms: d(V_c r_s)/dy_jq = V_c (dr_s/dsum_q + dr_s/dmean_q / W_c) L_cj / V_j, W_c = sum_j L_cj,
    // the partial derivatives by central differences in sum_q and mean_q.
    if (!neighbourhood_.empty()) {
      std::vector<double> nb(2 * S), dsum(S), dmean(S);
      for (std::size_t c = 0; c < n; ++c) {
        for (std::size_t q = 0; q < S; ++q) cc[q] = conc_[index(c, q)];
        std::copy_n(&neighbourhood_[c * 2 * S], 2 * S, nb.begin());
        for (std::size_t q = 0; q < S; ++q) {
          if (!reactions_->usesNeighbourhood(q)) continue;
          for (std::size_t which = 0; which < 2; ++which) {
            const std::size_t v = which * S + q;
            const double h = root * std::max(std::abs(nb[v]), 1.0);
            const double keep = nb[v];
            nb[v] = keep + h;
            evaluateReactions(t, c, cc, up, nb);
            nb[v] = keep - h;
            evaluateReactions(t, c, cc, down, nb);
            nb[v] = keep;
            for (std::size_t s = 0; s < S; ++s) (which == 0 ? dsum : dmean)[s] = (up[s] - down[s]) / (2 * h);
          }
          for (std::size_t f : neighbours_[c]) {
            const std::size_t j = otherCell(graph_.interfaces[f], c);
            const double L = graph_.interfaces[f].measure;
            for (std::size_t s = 0; s < S; ++s) {
              const double per_c = dsum[s] + (wall_total_[c] > 0 ? dmean[s] / wall_total_[c] : 0.0);
              addAt(J, index(c, s), index(j, q), graph_.measure[c] * per_c * L / graph_.measure[j]);
            }
          }
        }
      }
    }
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
      pin_weight_[c] = pin.weight(conc_[index(c, p)]);
      pin_weight_derivative_[c] = pin.weightDerivative(conc_[index(c, p)]);
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
  for (std::size_t c = 0; c < n; ++c) w[c] = pin.weight(y[index(c, p)] / graph_.measure[c]);
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
