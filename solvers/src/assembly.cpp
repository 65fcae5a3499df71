// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/solvers/assembly.hpp"

#include "assemble_detail.hpp"
#include "tessella/solvers/assembly_pattern.hpp"
#include "tessella/solvers/element_geometry.hpp"
#include "tessella/solvers/errors.hpp"

#include <sstream>
#include <string>

namespace tessella::solvers {

const EnumTable<MassType>& massTypes() {
  static const EnumTable<MassType> table(
      "mass matrix", {{"consistent", MassType::Consistent, "Exact integral of phi_i phi_j."},
                      {"lumped", MassType::Lumped, "Row-sum diagonal; keeps a positive solution positive."}});
  return table;
}

namespace {

void checkCoefficient(const Eigen::VectorXd& c, int expected, const char* what) {
  if (c.size() != 0 && c.size() != expected) {
    std::ostringstream msg;
    msg << what << ": " << c.size() << " coefficients for " << expected << " items";
    throw InvalidProblemError(msg.str());
  }
}

void checkFacets(const mesh::FeMesh& mesh, const std::vector<int>& facets) {
  for (int f : facets)
    if (f < 0 || f >= mesh.numWallFacets())
      throw InvalidProblemError("facet index " + std::to_string(f) + " out of range [0, " +
                                std::to_string(mesh.numWallFacets()) + ")");
}

// Consistent P1 mass of a k-simplex with n = k+1 nodes: |s|/(n(n+1)) * (1 + delta_ij).
template <typename Mat>
void simplexMass(double measure, int n, Mat& m) {
  const double off = measure / (n * (n + 1));
  m.setConstant(off);
  m.diagonal().array() += off;
}

}  // namespace

// One-off assemblies build the pattern for the call: less memory than n^2
// triplets per element. Repeated assemblies on one mesh should keep an
// AssemblyPattern instead.
SparseMatrix assembleMass(const mesh::FeMesh& mesh, MassType type, const Eigen::VectorXd& element_coefficient) {
  checkMesh(mesh);
  checkCoefficient(element_coefficient, mesh.numElements(), "assembleMass");
  return AssemblyPattern(mesh).mass(mesh, type, element_coefficient);
}

SparseMatrix assembleStiffness(const mesh::FeMesh& mesh, const Eigen::VectorXd& element_coefficient) {
  checkMesh(mesh);
  checkCoefficient(element_coefficient, mesh.numElements(), "assembleStiffness");
  return AssemblyPattern(mesh).stiffness(mesh, element_coefficient);
}

Eigen::VectorXd elementMeasures(const mesh::FeMesh& mesh) {
  checkMesh(mesh);
  Eigen::VectorXd measure(mesh.numElements());
  detail::parallelFor(mesh.numElements(), [&](int e) { measure[e] = elementGeometry(mesh, e).measure; });
  return measure;
}

Eigen::VectorXd assembleLoad(const mesh::FeMesh& mesh, const Eigen::VectorXd& element_density) {
  checkCoefficient(element_density, mesh.numElements(), "assembleLoad");
  const Eigen::VectorXd measure = elementMeasures(mesh);
  const int n = mesh.dim + 1;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.numNodes());
  // Serial scatter in element order: deterministic sums.
  for (int e = 0; e < mesh.numElements(); ++e) {
    const double share = (element_density.size() ? element_density[e] : 1.0) * measure[e] / n;
    for (int a = 0; a < n; ++a) F[mesh.elements(e, a)] += share;
  }
  return F;
}

SparseMatrix assembleFacetMass(const mesh::FeMesh& mesh, const std::vector<int>& facets,
                               const Eigen::VectorXd& facet_coefficient) {
  checkMesh(mesh);
  checkFacets(mesh, facets);
  checkCoefficient(facet_coefficient, static_cast<int>(facets.size()), "assembleFacetMass");
  const int n = mesh.dim;  // nodes per facet
  return detail::assembleElementwise(
      static_cast<int>(facets.size()), n, mesh.numNodes(), [&](int i, detail::LocalMatrix& ke, int* dofs) {
        const int f = facets[static_cast<std::size_t>(i)];
        for (int a = 0; a < n; ++a) dofs[a] = mesh.wall_facets(f, a);
        const double c = facet_coefficient.size() ? facet_coefficient[i] : 1.0;
        simplexMass(c * simplexMeasure(mesh, dofs, n), n, ke);
      });
}

Eigen::VectorXd assembleFacetLoad(const mesh::FeMesh& mesh, const std::vector<int>& facets,
                                  const Eigen::VectorXd& facet_density) {
  checkMesh(mesh);
  checkFacets(mesh, facets);
  if (facet_density.size() != static_cast<Eigen::Index>(facets.size()))
    throw InvalidProblemError("assembleFacetLoad: need one density per facet");
  const int n = mesh.dim;
  Eigen::VectorXd G = Eigen::VectorXd::Zero(mesh.numNodes());
  for (std::size_t i = 0; i < facets.size(); ++i) {
    int nodes[3];
    for (int a = 0; a < n; ++a) nodes[a] = mesh.wall_facets(facets[i], a);
    const double share = facet_density[static_cast<Eigen::Index>(i)] * simplexMeasure(mesh, nodes, n) / n;
    for (int a = 0; a < n; ++a) G[nodes[a]] += share;
  }
  return G;
}

}  // namespace tessella::solvers
