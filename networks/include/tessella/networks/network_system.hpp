// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// NetworkSystem: the ODE system of a NetworkModel on a NetworkGraph,
// dy/dt = F(t, y), and its Jacobian. The state is the AMOUNT of every species
// in every cell, y[c * S + s] (S species); the concentration is
// c = y / measure. Transport moves amount from one cell to another, so every
// transport term leaves the sum of a species' amounts unchanged (the
// Jacobian's transport part has zero column sums). With a PIN model that makes
// PIN a state (with_the_flux, expression) the PIN densities follow the amounts:
// y[numCells() * S + 2 k + side], the density on cell_i's (side 0) and on
// cell_j's (side 1) side of interface k. Equations: docs/networks.md.
//
// Not thread-safe (the reactions' muparser variables are members); rhs() and jacobian() can split
// their work over OpenMP threads cell by cell (setThreads), with results that do not depend on the
// number of threads.

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tessella/networks/network_graph.hpp"
#include "tessella/networks/network_model.hpp"
#include "tessella/tissue/enum_table.hpp"

namespace tessella::networks {

/// A sparse matrix in compressed rows: row r holds the entries
/// [row_start[r], row_start[r + 1]) of `column` and `value`, columns ascending.
struct CsrMatrix {
  std::size_t rows = 0;
  std::vector<std::size_t> row_start;
  std::vector<std::size_t> column;
  std::vector<double> value;
  /// The entry (r, c), 0 when outside the pattern.
  double at(std::size_t r, std::size_t c) const;
};

/// PIN on both sides of an interface: on cell_i's side toward cell_j (ij) and
/// on cell_j's side toward cell_i (ji).
struct PinSides {
  double ij = 0.0;
  double ji = 0.0;
};

class ReactionSet;
struct CellValues;
class PinExpression;

/// What jacobian() computes: `Exact`, dF/dy; `Neighbours`, dF/dy without the
/// entries that couple a cell with the neighbours of its neighbours (the
/// derivatives of a neighbour's PIN denominator), a sparser matrix (7 instead
/// of 19 entries per row on a hexagonal grid) that CVODE's Newton iteration
/// uses as an approximation. Both have zero column sums in the transport
/// part, so each conserves amounts.
enum class JacobianKind { Exact, Neighbours };
/// "exact", "neighbours".
const EnumTable<JacobianKind>& jacobianKinds();

class NetworkSystem {
 public:
  /// Validates both, compiles the reactions (InputError naming the species
  /// and muparser's message), and builds the Jacobian's pattern.
  NetworkSystem(NetworkModel model, NetworkGraph graph, JacobianKind jacobian = JacobianKind::Exact);
  ~NetworkSystem();
  NetworkSystem(const NetworkSystem&) = delete;
  NetworkSystem& operator=(const NetworkSystem&) = delete;

  const NetworkModel& model() const { return model_; }
  const NetworkGraph& graph() const { return graph_; }
  std::size_t numSpecies() const { return model_.species.size(); }
  std::size_t numCells() const { return graph_.numCells(); }
  /// Amounts, then PIN densities (numPinStates()).
  std::size_t size() const { return numSpecies() * numCells() + numPinStates(); }
  std::size_t index(std::size_t cell, std::size_t species) const { return cell * numSpecies() + species; }
  /// 2 per interface with a dynamic PIN model (PinTransport::dynamic()), else 0.
  std::size_t numPinStates() const { return model_.pin.dynamic() ? 2 * graph_.interfaces.size() : 0; }
  /// The state index of the PIN density on side 0 (cell_i's) or 1 (cell_j's) of interface k.
  std::size_t pinIndex(std::size_t k, int side) const {
    return numSpecies() * numCells() + 2 * k + static_cast<std::size_t>(side);
  }

  /// Whether `graph` has this system's structure: as many cells, the same interfaces (cell_i, cell_j) in the
  /// same order and the same cell properties. Measures, centroids and normals may differ.
  bool sameStructure(const NetworkGraph& graph) const;
  /// Replaces the graph by `graph` of the same structure (sameStructure; else InputError naming what
  /// differs), e.g. the same tissue after growth: the compiled reactions, the Jacobian's pattern and the
  /// neighbour arrays are kept, the measures, centroids, normals and property values are `graph`'s. The
  /// system then computes exactly what a new NetworkSystem(model(), graph) would.
  void updateGraph(NetworkGraph graph);

  /// The number of OpenMP threads rhs() and jacobian() split their cells over (0: OpenMP's default);
  /// 1 at construction. The results are the same for any number.
  void setThreads(std::size_t threads);
  std::size_t threads() const { return threads_; }

  /// dy/dt at (t, y) into ydot (both of size()). A reaction rate that is not
  /// finite is an InputError naming the species, the cell and the values.
  void rhs(double t, std::span<const double> y, std::span<double> ydot);
  /// The pattern of dF/dy (values zero): the species of a cell couple with
  /// each other (reactions), a transported species with its neighbours, and
  /// the PIN species with the neighbours of its neighbours (up_the_gradient,
  /// JacobianKind::Exact) or with its interfaces' PIN densities (dynamic PIN);
  /// a reaction reading sum_q / mean_q with q in the neighbours.
  const CsrMatrix& pattern() const { return pattern_; }
  /// dF/dy at (t, y) on pattern(): transport and PIN exactly, reactions by
  /// central differences per cell in the cell's concentrations and in its
  /// neighbourhood terms (then chained exactly), a PIN expression by central
  /// differences in its arguments; with JacobianKind::Neighbours without the
  /// second-neighbour terms of up_the_gradient.
  void jacobian(double t, std::span<const double> y, CsrMatrix& J);

  /// PIN on both sides of every interface at state y (zeros without PIN transport): the amount
  /// on the side, L_ij times the density.
  std::vector<PinSides> pin(std::span<const double> y) const;
  /// PIN per unit interface measure on both sides (0 on an interface of measure 0).
  std::vector<PinSides> pinDensity(std::span<const double> y) const;
  /// Per cell, sum over its interfaces of PIN (its side) times the unit
  /// normal pointing out of it: the cell's polarity vector.
  std::vector<Vec3> polarity(std::span<const double> y) const;

  /// sum over cells of the amounts of species s.
  double totalAmount(std::span<const double> y, std::size_t s) const;

 private:
  bool inPattern(std::size_t r, std::size_t c) const;
  // What depends on the graph's measures and property values: adjacent_measure_, wall_total_,
  // property_columns_.
  void readMeasures();
  // Empty when `graph` has this system's structure, else what differs.
  std::string structureDifference(const NetworkGraph& graph) const;
  void pinDenominators();  // pin_denominator_ from pin_weight_, and pin_out_
  // One ReactionSet and property buffer per OpenMP thread (muparser's variables are per parser).
  void prepareThreads();
  // up_the_gradient's f(c) and f'(c) (the exponential as exp(c ln b)).
  double pinWeight(double c) const;
  double pinWeightDerivative(double c) const;
  void neighbourhoodTerms();  // neighbourhood_ from conc_
  // What the reactions read at time t over all cells (conc_, neighbourhood_, the graph's measures, centroids
  // and property columns).
  CellValues cellValues(double t) const;
  // Dynamic PIN: pin_cell_ from y; the rate of the density on `side` of interface k and, if `partial`, its
  // derivatives with respect to the PinExpression arguments.
  void pinCellAmounts(std::span<const double> y);
  double pinRate(double t, std::size_t k, int side, std::span<const double> y, std::array<double, 8>* partial);

  NetworkModel model_;
  NetworkGraph graph_;
  std::vector<std::unique_ptr<ReactionSet>> reactions_;  // per thread
  std::vector<std::vector<std::size_t>> neighbours_;       // per cell: interface indices
  // The same in compressed rows: cell c's neighbours adjacent_cell_[k] and interface measures
  // adjacent_measure_[k] for k in [adjacent_start_[c], adjacent_start_[c + 1]), in neighbours_ order.
  std::vector<std::size_t> adjacent_start_, adjacent_cell_;
  std::vector<double> adjacent_measure_;
  CsrMatrix pattern_;
  // With reactions, per row index(c, s): the position in pattern_ of column index(c, 0) (the cell's own
  // concentrations are the consecutive entries from there).
  std::vector<std::size_t> reaction_entry_;
  JacobianKind jacobian_kind_ = JacobianKind::Exact;
  int pin_species_ = -1;
  std::vector<double> pin_denominator_, pin_weight_, pin_weight_derivative_, conc_;
  std::vector<double> permeability_;  // per species
  std::vector<double> pin_out_;  // per cell: T P_tot c_i / D_i, the efflux per unit L_ij f(c_j)
  double log_base_ = 0.0;        // ln b of the exponential PIN weight
  std::size_t threads_ = 1;
  std::unique_ptr<PinExpression> pin_expression_;
  bool pin_cell_coupled_ = false;  // a PIN rate reads every PIN of its cell (bounded, or pin_cell in the expression)
  std::vector<double> pin_cell_;   // per cell: sum_k L_ik p_ik
  // Per cell, the reactions' sum_<s> then mean_<s> of every species (empty when no reaction reads them), and
  // the cell's summed interface measure.
  std::vector<double> neighbourhood_, wall_total_;
  std::vector<const std::vector<double>*> property_columns_;  // the model's cell properties in the graph
  std::vector<std::vector<double>> property_values_;          // per thread, one cell's values of them
};

}  // namespace tessella::networks
