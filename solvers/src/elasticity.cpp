// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/solvers/elasticity.hpp"

#include "assemble_detail.hpp"
#include "dof_reduction.hpp"
#include "tessella/solvers/element_geometry.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/solvers/facets.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>  // cross product
#include <Eigen/SVD>

#include <cmath>
#include <sstream>

namespace tessella::solvers {

const EnumTable<ElasticModel>& elasticModels() {
  static const EnumTable<ElasticModel> table(
      "elastic model", {{"plane_stress", ElasticModel::PlaneStress, "Flat 2D tissue, thin in z."},
                        {"plane_strain", ElasticModel::PlaneStrain, "Flat 2D tissue, long in z."},
                        {"solid", ElasticModel::Solid, "3D tissue on tetrahedra."},
                        {"membrane", ElasticModel::Membrane, "Curved sheet: in-plane stress, no bending."}});
  return table;
}

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using StrainB = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 12>;

// Elasticity matrix in the model's own Voigt space (3 entries in 2D, 6 in 3D).
Eigen::MatrixXd elasticityMatrix(ElasticModel model, double E, double nu) {
  if (model == ElasticModel::Solid) {
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(6, 6);
    D.topLeftCorner(3, 3).setConstant(lambda);
    D.topLeftCorner(3, 3).diagonal().array() += 2 * mu;
    D.bottomRightCorner(3, 3).diagonal().setConstant(mu);
    return D;
  }
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(3, 3);
  if (model == ElasticModel::PlaneStress || model == ElasticModel::Membrane) {
    const double c = E / (1 - nu * nu);
    D << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  } else {
    const double c = E / ((1 + nu) * (1 - 2 * nu));
    D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;
  }
  return D;
}

// Strain-displacement matrix from the hat-function gradients.
StrainB strainMatrix(const ElementGeometry& g, int dim) {
  const int nn = dim + 1;
  StrainB B = StrainB::Zero(dim == 3 ? 6 : 3, dim * nn);
  for (int a = 0; a < nn; ++a) {
    const double gx = g.gradients(a, 0), gy = g.gradients(a, 1), gz = g.gradients(a, 2);
    if (dim == 3) {
      const int c = 3 * a;
      B(0, c) = gx;
      B(1, c + 1) = gy;
      B(2, c + 2) = gz;
      B(3, c + 1) = gz, B(3, c + 2) = gy;
      B(4, c) = gz, B(4, c + 2) = gx;
      B(5, c) = gy, B(5, c + 1) = gx;
    } else {
      const int c = 2 * a;
      B(0, c) = gx;
      B(1, c + 1) = gy;
      B(2, c) = gy, B(2, c + 1) = gx;
    }
  }
  return B;
}

// Orthonormal in-plane frame [e1 e2] of a triangle in R^3 (e1 along its first
// edge) and its unit normal n = e1 x e2, along (x1 - x0) x (x2 - x0).
struct MembraneFrame {
  Eigen::Matrix<double, 3, 2> Q;
  Eigen::Vector3d normal;
};

MembraneFrame membraneFrame(const mesh::FeMesh& mesh, int e) {
  const Eigen::Vector3d x0 = mesh.nodes.row(mesh.elements(e, 0)).transpose();
  const Eigen::Vector3d a = mesh.nodes.row(mesh.elements(e, 1)).transpose() - x0;
  const Eigen::Vector3d b = mesh.nodes.row(mesh.elements(e, 2)).transpose() - x0;
  MembraneFrame f;
  f.normal = a.cross(b).normalized();
  f.Q.col(0) = a.normalized();
  f.Q.col(1) = f.normal.cross(f.Q.col(0));
  return f;
}

// In-plane strain [e11, e22, gamma12] of a membrane triangle from its nine
// nodal displacement components: e_ij = sym(e_i . (sum_a u_a (x) grad phi_a) e_j),
// the tangential gradients of elementGeometry projected on the frame.
StrainB membraneStrainMatrix(const ElementGeometry& g, const MembraneFrame& f) {
  StrainB B = StrainB::Zero(3, 9);
  const Eigen::Vector3d e1 = f.Q.col(0), e2 = f.Q.col(1);
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d grad = g.gradients.row(a).transpose();
    const double g1 = grad.dot(e1), g2 = grad.dot(e2);
    for (int c = 0; c < 3; ++c) {
      B(0, 3 * a + c) = e1[c] * g1;
      B(1, 3 * a + c) = e2[c] * g2;
      B(2, 3 * a + c) = e1[c] * g2 + e2[c] * g1;
    }
  }
  return B;
}

// Voigt [xx, yy, zz, yz, xz, xy] of a symmetric tensor; engineering shears when `strain`.
Eigen::Matrix<double, 1, 6> tensorToVoigt(const Eigen::Matrix3d& t, bool strain) {
  const double k = strain ? 2.0 : 1.0;
  Eigen::Matrix<double, 1, 6> v;
  v << t(0, 0), t(1, 1), t(2, 2), k * t(1, 2), k * t(0, 2), k * t(0, 1);
  return v;
}

[[noreturn]] void bad(const std::string& what) { throw InvalidProblemError("elasticity: " + what); }

// Rigid-body modes evaluated on the fixed dofs must have full rank (3 in 2D,
// 6 in 3D); otherwise some translation/rotation is left free and K_FF is singular.
void checkRigidModes(const mesh::FeMesh& mesh, int nc, const std::vector<int>& fixed_dofs) {
  const int modes = nc == 3 ? 6 : 3;
  if (fixed_dofs.empty())
    bad("no displacement constraints: a pure traction/pressure problem has rigid-body modes and no unique solution; "
        "fix at least enough displacement components to prevent translation and rotation");
  const Eigen::RowVector3d center = mesh.nodes.colwise().mean();
  const double scale = std::max((mesh.nodes.rowwise() - center).cwiseAbs().maxCoeff(), 1e-300);
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(fixed_dofs.size()), modes);
  for (std::size_t k = 0; k < fixed_dofs.size(); ++k) {
    const int node = fixed_dofs[k] / nc, comp = fixed_dofs[k] % nc;
    const Eigen::Vector3d x = (mesh.nodes.row(node) - center).transpose() / scale;
    const auto r = static_cast<Eigen::Index>(k);
    R(r, comp) = 1.0;  // translations
    if (nc == 2) {
      R(r, 2) = comp == 0 ? -x.y() : x.x();  // in-plane rotation (-y, x)
    } else {
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(comp);
      for (int a = 0; a < 3; ++a) R(r, 3 + a) = Eigen::Vector3d::Unit(a).cross(x).dot(e);  // (e_a x x)_comp
    }
  }
  const Eigen::MatrixXd gram = R.transpose() * R;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
  const Eigen::VectorXd ev = eig.eigenvalues();  // ascending
  const double largest = std::max(ev[modes - 1], 1.0);
  int free_modes = 0;
  for (int k = 0; k < modes; ++k) free_modes += ev[k] <= 1e-12 * largest ? 1 : 0;
  if (free_modes > 0) {
    std::ostringstream msg;
    msg << "under-constrained: the " << fixed_dofs.size() << " fixed displacement components leave " << free_modes
        << " of the " << modes << " rigid-body modes (translations/rotations) free, so the stiffness matrix is "
        << "singular; fix more components";
    bad(msg.str());
  }
}

}  // namespace

Eigen::Matrix3d voigtToTensor(const Eigen::Matrix<double, 1, 6>& v) {
  Eigen::Matrix3d t;
  t << v[0], v[5], v[4], v[5], v[1], v[3], v[4], v[3], v[2];
  return t;
}

ElasticityResult solveElasticity(const mesh::FeMesh& mesh, const ElasticityProblem& problem) {
  checkMesh(mesh);
  const ElasticModel model = problem.model;
  const bool membrane = model == ElasticModel::Membrane;
  const int dim = mesh.dim;
  if ((model == ElasticModel::Solid) != (dim == 3))
    bad(model == ElasticModel::Solid ? "the 3D (Solid) model needs a tetrahedral mesh (dim 3)"
                                     : "plane stress/strain and membranes need a triangle mesh (dim 2)");
  if (dim == 2 && !membrane) {
    const double extent = std::max(mesh.nodes.cwiseAbs().maxCoeff(), 1e-300);
    if (mesh.numNodes() > 0 && (mesh.nodes.col(2).array() - mesh.nodes(0, 2)).abs().maxCoeff() > 1e-12 * extent)
      bad("plane stress/strain needs a flat mesh in the xy-plane (use the Membrane model for curved or tilted sheets)");
  }
  if (!membrane && problem.membrane_pressure != 0.0) bad("membrane_pressure needs the Membrane model");
  if (!std::isfinite(problem.membrane_pressure)) bad("membrane_pressure must be finite");
  if (!(problem.thickness > 0.0)) bad("thickness must be > 0");
  const Eigen::VectorXd E = cellToElement(mesh, problem.young, "elasticity: Young's modulus", true);
  const Eigen::VectorXd nu = cellToElement(mesh, problem.poisson, "elasticity: Poisson's ratio");
  for (int e = 0; e < mesh.numElements(); ++e) {
    if (!(E[e] > 0.0)) bad("Young's modulus of cell " + std::to_string(mesh.element_cell[e]) + " must be > 0");
    if (!(nu[e] > -1.0 && nu[e] < 0.5))
      bad("Poisson's ratio of cell " + std::to_string(mesh.element_cell[e]) + " must be in (-1, 0.5)");
  }
  const int nc = membrane ? 3 : dim;  // displacement components
  const int nn = dim + 1;
  const int ndof = nc * mesh.numNodes();
  const double thick = dim == 2 ? problem.thickness : 1.0;
  auto elementStrainMatrix = [&](int e, const ElementGeometry& g) {
    return membrane ? membraneStrainMatrix(g, membraneFrame(mesh, e)) : strainMatrix(g, dim);
  };

  // Element stiffness t |e| B^T D B, assembled deterministically in parallel.
  const SparseMatrix K = detail::assembleElementwise(
      mesh.numElements(), nc * nn, ndof, [&](int e, detail::LocalMatrix& ke, int* dofs) {
        const ElementGeometry g = elementGeometry(mesh, e);
        const StrainB B = elementStrainMatrix(e, g);
        const Eigen::MatrixXd D = elasticityMatrix(model, E[e], nu[e]);
        ke.noalias() = (thick * g.measure) * (B.transpose() * D * B);
        for (int a = 0; a < nn; ++a)
          for (int c = 0; c < nc; ++c) dofs[nc * a + c] = nc * mesh.elements(e, a) + c;
      });

  // Loads: body force, tractions, pressures (constant per facet: exact P1 integrals).
  Eigen::VectorXd F = Eigen::VectorXd::Zero(ndof);
  if (!problem.body_force.isZero(0.0)) {
    for (int e = 0; e < mesh.numElements(); ++e) {
      const double share = thick * elementGeometry(mesh, e).measure / nn;
      for (int a = 0; a < nn; ++a)
        for (int c = 0; c < nc; ++c) F[nc * mesh.elements(e, a) + c] += share * problem.body_force[c];
    }
  }
  if (problem.membrane_pressure != 0.0) {
    for (int e = 0; e < mesh.numElements(); ++e) {
      const Eigen::Vector3d f =
          (problem.membrane_pressure * elementGeometry(mesh, e).measure / 3.0) * membraneFrame(mesh, e).normal;
      for (int a = 0; a < 3; ++a) F.segment<3>(3 * mesh.elements(e, a)) += f;
    }
  }
  auto addFacetForce = [&](int f, const Eigen::Vector3d& t) {
    int nodes[3];
    for (int a = 0; a < dim; ++a) nodes[a] = mesh.wall_facets(f, a);
    const double share = thick * simplexMeasure(mesh, nodes, dim) / dim;
    for (int a = 0; a < dim; ++a)
      for (int c = 0; c < nc; ++c) F[nc * nodes[a] + c] += share * t[c];
  };
  for (const TractionCondition& tc : problem.traction)
    for (int f : tc.facets) {
      if (f < 0 || f >= mesh.numWallFacets()) bad("traction facet index " + std::to_string(f) + " out of range");
      addFacetForce(f, tc.traction);
    }
  for (const PressureCondition& pc : problem.pressure) {
    const std::vector<FacetSide> sides = facetSides(mesh, pc.facets);
    for (std::size_t i = 0; i < pc.facets.size(); ++i) {
      const int f = pc.facets[i];
      if (!mesh.facet_on_boundary[f])
        bad("pressure on interior wall facet " + std::to_string(f) + ": pressure is only defined on the boundary");
      addFacetForce(f, -pc.pressure * outwardNormal(mesh, f, sides[i]));
    }
  }

  // Displacement conditions (later conditions win on shared nodes).
  std::vector<char> fixed(static_cast<std::size_t>(ndof), 0);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(ndof);
  for (const DisplacementCondition& dc : problem.displacement) {
    std::vector<int> nodes = facetNodes(mesh, dc.facets);
    for (int i : dc.nodes) {
      if (i < 0 || i >= mesh.numNodes()) bad("displacement node index " + std::to_string(i) + " out of range");
      nodes.push_back(i);
    }
    for (int i : nodes)
      for (int c = 0; c < nc; ++c)
        if (dc.fixed[static_cast<std::size_t>(c)]) {
          fixed[static_cast<std::size_t>(nc * i + c)] = 1;
          g[nc * i + c] = dc.value[c];
        }
  }
  const detail::DofReduction red(fixed);
  checkRigidModes(mesh, nc, red.fixedDofs());

  SparseMatrix Kff, Kfc;
  red.split(K, Kff, Kfc);
  LinearSolver solver(problem.linear);
  try {
    solver.compute(Kff);
  } catch (const FactorizationError& err) {
    bad(std::string("stiffness matrix is singular or indefinite after applying the displacement conditions") +
        (membrane ? " (a membrane has no bending stiffness: a flat or open curved sheet needs its normal "
                    "displacement fixed wherever it could fold without stretching)"
                  : "") +
        ": " + err.what());
  }
  Eigen::VectorXd b = red.freePart(F);
  if (red.numFixed() > 0) b -= Kfc * red.fixedPart(g);
  Eigen::VectorXd u = g;
  red.scatterFree(solver.solve(b), u);

  ElasticityResult out;
  out.report = solver.lastReport();
  out.displacement = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>::Zero(mesh.numNodes(), 3);
  for (int i = 0; i < mesh.numNodes(); ++i)
    for (int c = 0; c < nc; ++c) out.displacement(i, c) = u[nc * i + c];

  // Strain and stress per element, expanded to 6-component Voigt.
  out.strain.resize(mesh.numElements(), 6);
  out.stress.resize(mesh.numElements(), 6);
  Eigen::VectorXd measure(mesh.numElements());
  detail::parallelFor(mesh.numElements(), [&](int e) {
    const ElementGeometry geo = elementGeometry(mesh, e);
    measure[e] = geo.measure;
    const StrainB B = elementStrainMatrix(e, geo);
    Eigen::VectorXd ue(nc * nn);
    for (int a = 0; a < nn; ++a)
      for (int c = 0; c < nc; ++c) ue[nc * a + c] = u[nc * mesh.elements(e, a) + c];
    const Eigen::VectorXd eps = B * ue;
    const Eigen::VectorXd sig = elasticityMatrix(model, E[e], nu[e]) * eps;
    Eigen::Matrix<double, 1, 6> es = Eigen::Matrix<double, 1, 6>::Zero(), ss = es;
    if (dim == 3) {
      es = eps.transpose();
      ss = sig.transpose();
    } else if (membrane) {
      // Local 2x2 tensors rotated to global axes: Q t Q^T (+ the normal strain).
      const MembraneFrame f = membraneFrame(mesh, e);
      Eigen::Matrix2d el, sl;
      el << eps[0], eps[2] / 2, eps[2] / 2, eps[1];
      sl << sig[0], sig[2], sig[2], sig[1];
      const double enn = -nu[e] / (1 - nu[e]) * (eps[0] + eps[1]);
      es = tensorToVoigt(f.Q * el * f.Q.transpose() + enn * f.normal * f.normal.transpose(), true);
      ss = tensorToVoigt(f.Q * sl * f.Q.transpose(), false);
    } else {
      es << eps[0], eps[1], 0, 0, 0, eps[2];
      ss << sig[0], sig[1], 0, 0, 0, sig[2];
      if (model == ElasticModel::PlaneStress)
        es[2] = -nu[e] / (1 - nu[e]) * (eps[0] + eps[1]);
      else
        ss[2] = nu[e] * (sig[0] + sig[1]);
    }
    out.strain.row(e) = es;
    out.stress.row(e) = ss;
  });

  // Cell averages (serial, element order: deterministic) and principal stresses.
  const int cells = numCells(mesh);
  out.cell_stress = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>::Zero(cells, 6);
  out.cell_strain = out.cell_stress;
  Eigen::VectorXd cell_measure = Eigen::VectorXd::Zero(cells);
  for (int e = 0; e < mesh.numElements(); ++e) {
    out.cell_stress.row(mesh.element_cell[e]) += measure[e] * out.stress.row(e);
    out.cell_strain.row(mesh.element_cell[e]) += measure[e] * out.strain.row(e);
    cell_measure[mesh.element_cell[e]] += measure[e];
  }
  out.principal_stress = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>::Zero(cells, 3);
  out.principal_directions.assign(static_cast<std::size_t>(cells), Eigen::Matrix3d::Identity());
  for (int c = 0; c < cells; ++c) {
    if (cell_measure[c] <= 0.0) continue;  // cell id without elements
    out.cell_stress.row(c) /= cell_measure[c];
    out.cell_strain.row(c) /= cell_measure[c];
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(voigtToTensor(out.cell_stress.row(c)));
    out.principal_stress.row(c) = eig.eigenvalues().transpose();
    out.principal_directions[static_cast<std::size_t>(c)] = eig.eigenvectors();
  }
  return out;
}

}  // namespace tessella::solvers
