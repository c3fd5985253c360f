#include "solver/assembler3d.hpp"

#include <algorithm>
#include <array>
#include <thread>

#include "core/constants.hpp"
#include "core/parallel_scatter.hpp"
#include "core/thread_count.hpp"
#include "solver/coil_source3d.hpp"
#include "solver/tet_lagrange.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {

// A symmetry plane with `field: normal` (n x H = 0) holds u = 0. Why zero, with magnets,
// coils and total-potential iron alike: the whole device is its own mirror image there
// (mesh/symmetry_plane3d.hpp), under which the reduced potential u is odd (H - H_s and H_s are
// both mirror fields, and u vanishes at infinity), so it is 0 on the plane. In total regions
// u + I_h Phi_s is the total potential; Phi_s is constant on the plane within an iron
// component (H_s . dl = 0 along it, up to the edge quadrature), so u = 0 keeps that potential
// constant there, which is n x H = 0. `field: parallel` (B . n = 0) is the natural condition
// of the weak form in the total B: nothing to impose.
std::vector<int> constrained_dofs(const Problem3D& problem, const DofMap3D& dofs) {
  const Mesh3D& mesh = *problem.mesh;
  std::vector<std::array<int, 3>> faces;
  for (std::size_t p = 0; p < mesh.symmetry.size(); ++p)
    if (mesh.symmetry[p].field == SymmetryField::normal)
      faces.insert(faces.end(), mesh.symmetry_faces[p].begin(), mesh.symmetry_faces[p].end());
  if (problem.boundary == OuterKind3D::neumann) {
    if (faces.empty())
      return {0}; // gauge: phi up to a constant
    return dofs.dofs_on_faces(faces);
  }
  faces.insert(faces.end(), mesh.outer_faces.begin(), mesh.outer_faces.end());
  return dofs.dofs_on_faces(faces);
}

bool problem_is_linear(const Problem3D& problem) {
  for (const auto& p : problem.parts)
    if (p.material->is_nonlinear())
      return false;
  return !problem.air.material->is_nonlinear();
}

std::vector<int> number_equations(int n_dofs, const std::vector<int>& constrained, int& n_eqs) {
  std::vector<int> map(n_dofs, 0);
  for (int d : constrained)
    map[d] = -1;
  n_eqs = 0;
  for (int& m : map)
    if (m == 0)
      m = n_eqs++;
  return map;
}

std::vector<int> equations_of_elements(const Mesh3D& mesh, const DofMap3D& dofs,
                                       const std::vector<int>& dof_to_eq) {
  const int per = dofs.dofs_per_element();
  std::vector<int> eqs(mesh.n_tets() * per);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    for (int i = 0; i < per; ++i)
      eqs[t * per + i] = dof_to_eq[dofs.element_dofs(t)[i]];
  return eqs;
}

// The pattern of the given tetrahedra only (own-row assembly), else of all.
SparsePattern pattern_of(int n_eqs, const std::vector<int>& element_eqs, int per,
                         const std::vector<std::size_t>* elements) {
  if (!elements)
    return SparsePattern(n_eqs, element_eqs, per);
  std::vector<int> eqs;
  eqs.reserve(elements->size() * per);
  for (std::size_t t : *elements)
    eqs.insert(eqs.end(), element_eqs.begin() + t * per, element_eqs.begin() + (t + 1) * per);
  return SparsePattern(n_eqs, eqs, per);
}

} // namespace

Assembler3D::Assembler3D(const Problem3D& problem, const DofMap3D& dofs, AssemblyOptions3D options)
    : problem_(problem), dofs_(dofs),
      options_(options), shell_{problem.mesh->shell_inner_radius, problem.mesh->shell_outer_radius},
      dof_to_eq_(number_equations(dofs.n_dofs(), constrained_dofs(problem, dofs), n_eqs_)),
      element_eqs_(equations_of_elements(*problem.mesh, dofs, dof_to_eq_)),
      linear_(problem_is_linear(problem)),
      pattern_(pattern_of(n_eqs_, element_eqs_, dofs.dofs_per_element(), options_.elements.get())) {
  if (problem_.source && problem_.source->active())
    source_load_ = source_load(-1);
}

// The residual at phi = 0 is minus the external load (remanence and coils). Not evaluated in
// the constructor: Newton's first evaluation is at zero and remembers it (evaluate), which
// saved a whole residual pass of every solve (benchmark32: 1.6 M P2 tets), and the
// distributed solve's shares never ask (DistributedSystem3D sums its own).
double Assembler3D::load_norm() const {
  if (load_norm_ < 0) {
    Eigen::VectorXd r;
    evaluate(Eigen::VectorXd::Zero(n_eqs_), r, nullptr, TangentKind::newton);
  }
  return load_norm_;
}

Eigen::VectorXd Assembler3D::expand(const Eigen::VectorXd& u) const {
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(dofs_.n_dofs());
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (dof_to_eq_[d] >= 0)
      phi[d] = u[dof_to_eq_[d]];
  return phi;
}

Eigen::VectorXd Assembler3D::restrict_to_free(const Eigen::VectorXd& phi_full) const {
  Eigen::VectorXd u(n_eqs_);
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (dof_to_eq_[d] >= 0)
      u[dof_to_eq_[d]] = phi_full[d];
  return u;
}

void Assembler3D::element(std::size_t t, const Eigen::VectorXd& phi_full, double* re, double* ke,
                          TangentKind kind, bool start_law) const {
  const auto& mesh = *problem_.mesh;
  const auto& tet = mesh.tets[t];
  const auto& nodes = mesh.nodes;
  const auto g = TetGeometry::of(nodes[tet[0]], nodes[tet[1]], nodes[tet[2]], nodes[tet[3]]);
  const int order = dofs_.order();
  const int n = dofs_.dofs_per_element();
  const int* dof = dofs_.element_dofs(t);
  const bool in_shell = problem_.is_shell(t);
  const RegionPhysics3D& phys = problem_.physics(mesh.tet_part[t]);
  const Material& mat = *phys.material;
  const bool radial =
      mat.is_magnet() && phys.magnetization.pattern == Magnetization::Pattern::radial;
  // Elements with edge nodes on curved surfaces use the isoparametric map.
  const bool curved = dofs_.is_curved(t);
  std::array<Eigen::Vector3d, 10> xn;
  if (curved)
    for (int i = 0; i < n; ++i)
      xn[i] = dofs_.dof_points()[dof[i]];
  // grad N_i . grad N_j has degree 2(order-1); the shell metric, nonlinear laws and radial
  // remanence are not polynomial and get the degree-5 rule, as do curved elements.
  const CoilSource3D* src = problem_.source;
  const bool coils = src && src->active();
  const bool total = coils && src->is_total(t);
  // Reduced nonlinear elements (iron that links a coil) need H_s inside the law; linear
  // reduced elements take H_s through the precomputed source load.
  const bool source_inside = coils && !total && !in_shell && mat.is_nonlinear();
  std::array<double, 10> value;
  for (int i = 0; i < n; ++i)
    value[i] = phi_full[dof[i]] + (total ? src->offset[dof[i]] : 0.0);
  // (The coil source table is sampled on the same rule: reduced nonlinear elements read it.)
  const int degree = (in_shell || mat.is_nonlinear() || radial || curved)
                         ? SourceFieldTable3D::rule_degree
                         : 2 * (order - 1);

  std::fill(re, re + n, 0.0);
  if (ke)
    std::fill(ke, ke + n * n, 0.0);
  std::array<Eigen::Vector3d, 10> grad, dgrad;
  const auto& rule = tet_rule(degree);
  for (std::size_t qi = 0; qi < rule.size(); ++qi) {
    const TetQuadPoint& q = rule[qi];
    Eigen::Vector3d x;
    double w = 0;
    if (curved) {
      w = q.weight * tet_iso_gradients(xn, q.bary, grad.data(), x);
    } else {
      tet_gradients(order, g, q.bary, grad.data());
      w = q.weight * g.volume;
      x = q.bary[0] * nodes[tet[0]] + q.bary[1] * nodes[tet[1]] + q.bary[2] * nodes[tet[2]] +
          q.bary[3] * nodes[tet[3]];
    }
    Eigen::Vector3d grad_phi = Eigen::Vector3d::Zero();
    for (int i = 0; i < n; ++i)
      grad_phi += value[i] * grad[i];
    Eigen::Matrix3d d;
    Eigen::Vector3d flux; // -B (or its shell-metric counterpart)
    if (in_shell) {
      // Air in the mapped exterior: -B' = mu0 T grad phi, tangent mu0 T.
      d = mu0 * shell_.metric<3>(x);
      flux = d * grad_phi;
    } else {
      Eigen::Vector3d h = -grad_phi;
      if (source_inside) // nonlinear: the degree of the source table's rule
        h += src->table.H(t, static_cast<int>(qi));
      double mu = 0, dmu = 0;
      if (start_law)
        mu = mat.start_permeability();
      else
        mat.permeability(h.squaredNorm(), mu, dmu);
      flux = -mu * h;
      if (mat.is_magnet())
        flux -= mat.B_r * phys.magnetization.unit_at(x);
      d = mu * Eigen::Matrix3d::Identity();
      if (kind == TangentKind::newton && dmu != 0)
        d += 2 * dmu * h * h.transpose();
    }
    for (int i = 0; i < n; ++i)
      re[i] += w * grad[i].dot(flux);
    if (!ke)
      continue;
    for (int j = 0; j < n; ++j)
      dgrad[j] = w * (d * grad[j]);
    for (int i = 0; i < n; ++i)
      for (int j = i; j < n; ++j)
        ke[i * n + j] += grad[i].dot(dgrad[j]);
  }
  if (ke)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < i; ++j)
        ke[i * n + j] = ke[j * n + i];
}

int Assembler3D::loop_threads() const {
  if (options_.threads > 0)
    return options_.threads;
  return element_loop_threads(share_count());
}

std::size_t Assembler3D::share_first() const {
  return std::min(options_.share.first, problem_.mesh->n_tets());
}

std::size_t Assembler3D::share_count() const {
  if (options_.elements)
    return options_.elements->size();
  return std::min(options_.share.last, problem_.mesh->n_tets()) - share_first();
}

void Assembler3D::evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                           Eigen::SparseMatrix<double>* matrix, TangentKind kind) const {
  assemble(u, residual, matrix, kind, false);
  // At u = 0 the residual is the load's whatever the tangent kind and matrix (they change
  // only the tangent): its norm is load_norm(), the same bits as evaluating it apart.
  if (load_norm_ < 0 && u.isZero(0))
    load_norm_ = residual.norm();
}

bool Assembler3D::start_problem(Eigen::VectorXd& residual,
                                Eigen::SparseMatrix<double>& matrix) const {
  if (linear_)
    return false;
  assemble(Eigen::VectorXd::Zero(n_eqs_), residual, &matrix, TangentKind::newton, true);
  return true;
}

void Assembler3D::assemble(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                           Eigen::SparseMatrix<double>* matrix, TangentKind kind,
                           bool start_law) const {
  const Eigen::VectorXd phi_full = expand(u);
  residual = Eigen::VectorXd::Zero(n_eqs_);
  if (matrix)
    *matrix = pattern_.zero_matrix();
  if (source_load_.size() > 0)
    residual = source_load_;
  const int n = dofs_.dofs_per_element();
  double* values = matrix ? matrix->valuePtr() : nullptr;
  // Equation i owns residual entry i and the stored matrix row i (the lower triangle keeps
  // local (i, j) at global row eq[i]), so each entry is summed by one thread in element order.
  parallel_element_scatter(
      share_count(), n + (matrix ? n * n : 0), n_eqs_, loop_threads(),
      [&](std::size_t e, double* out) {
        element(share_tet(e), phi_full, out, matrix ? out + n : nullptr, kind, start_law);
      },
      [&](std::size_t e, const double* re, std::size_t lo, std::size_t hi) {
        const std::size_t t = share_tet(e);
        const int* eq = &element_eqs_[t * n];
        const int* slot = matrix ? pattern_.slots(pattern_element(e)) : nullptr;
        for (int i = 0; i < n; ++i) {
          if (eq[i] < 0 || static_cast<std::size_t>(eq[i]) < lo ||
              static_cast<std::size_t>(eq[i]) >= hi)
            continue;
          residual[eq[i]] += re[i];
          if (!matrix)
            continue;
          for (int j = 0; j < n; ++j)
            if (slot[i * n + j] >= 0)
              values[slot[i * n + j]] += re[n + i * n + j];
        }
      });
}

void Assembler3D::element_source(std::size_t t, int coil, int n_coils, double* re) const {
  const auto& mesh = *problem_.mesh;
  const CoilSource3D& src = *problem_.source;
  const int n = dofs_.dofs_per_element();
  std::fill(re, re + n * n_coils, 0.0);
  const Material& mat = *problem_.physics(mesh.tet_part[t]).material;
  const bool in_shell = problem_.is_shell(t);
  if (src.is_total(t) || (!in_shell && mat.is_nonlinear()))
    return;
  const auto& tet = mesh.tets[t];
  const auto& nodes = mesh.nodes;
  const auto g = TetGeometry::of(nodes[tet[0]], nodes[tet[1]], nodes[tet[2]], nodes[tet[3]]);
  const int* dof = dofs_.element_dofs(t);
  const bool curved = dofs_.is_curved(t);
  std::array<Eigen::Vector3d, 10> xn;
  if (curved)
    for (int i = 0; i < n; ++i)
      xn[i] = dofs_.dof_points()[dof[i]];
  double mu = mu0, dmu = 0;
  if (!in_shell)
    mat.permeability(0.0, mu, dmu);
  std::array<Eigen::Vector3d, 10> grad;
  // H_s is not polynomial: the source table's degree-5 rule, as for the other
  // non-polynomial integrands.
  const auto& rule = tet_rule(SourceFieldTable3D::rule_degree);
  for (std::size_t qi = 0; qi < rule.size(); ++qi) {
    const TetQuadPoint& q = rule[qi];
    Eigen::Vector3d x;
    double w = 0;
    if (curved) {
      w = q.weight * tet_iso_gradients(xn, q.bary, grad.data(), x);
    } else {
      tet_gradients(dofs_.order(), g, q.bary, grad.data());
      w = q.weight * g.volume;
      x = q.bary[0] * nodes[tet[0]] + q.bary[1] * nodes[tet[1]] + q.bary[2] * nodes[tet[2]] +
          q.bary[3] * nodes[tet[3]];
    }
    // The table holds H_s at the mapped point shell_.map(x) in shell tets.
    const int qn = static_cast<int>(qi);
    const Eigen::Matrix3d d = in_shell ? Eigen::Matrix3d(mu0 * shell_.det_times_inverse_jacobian(x))
                                       : Eigen::Matrix3d(mu * Eigen::Matrix3d::Identity());
    for (int c = 0; c < n_coils; ++c) {
      const Eigen::Vector3d hs =
          coil < 0 ? src.table.H(t, qn) : src.table.H_per_ampere(t, qn, coil + c);
      const Eigen::Vector3d b = d * hs;
      for (int i = 0; i < n; ++i)
        re[c * n + i] -= w * grad[i].dot(b);
    }
  }
}

Eigen::VectorXd Assembler3D::source_load(int coil) const {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(n_eqs_);
  const int n = dofs_.dofs_per_element();
  parallel_element_scatter(
      share_count(), n, n_eqs_, loop_threads(),
      [&](std::size_t e, double* re) { element_source(share_tet(e), coil, 1, re); },
      [&](std::size_t e, const double* re, std::size_t lo, std::size_t hi) {
        const int* eq = &element_eqs_[share_tet(e) * n];
        for (int i = 0; i < n; ++i)
          if (eq[i] >= 0 && static_cast<std::size_t>(eq[i]) >= lo &&
              static_cast<std::size_t>(eq[i]) < hi && re[i] != 0)
            load[eq[i]] += re[i];
      });
  return load;
}

Eigen::VectorXd Assembler3D::current_derivative(const Eigen::VectorXd& u, int coil,
                                                TangentKind kind) const {
  return current_derivative_columns(u, coil, 1, kind).col(0);
}

Eigen::MatrixXd Assembler3D::current_derivatives(const Eigen::VectorXd& u, TangentKind kind) const {
  return current_derivative_columns(u, 0, problem_.source->field->n_coils(), kind);
}

Eigen::MatrixXd Assembler3D::current_derivative_columns(const Eigen::VectorXd& u, int first,
                                                        int count, TangentKind kind) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n_eqs_, count);
  const CoilSource3D& src = *problem_.source;
  const Eigen::VectorXd phi_full = expand(u);
  const int n = dofs_.dofs_per_element();
  // Reduced regions: the source field's load per ampere. Total regions: r depends on the
  // current through u + I Phi_s, so dr/dI = K_e Phi_s, one element tangent for every coil.
  parallel_element_scatter(
      share_count(), static_cast<std::size_t>(n * count), n_eqs_, loop_threads(),
      [&](std::size_t e, double* sum) {
        const std::size_t t = share_tet(e);
        if (!src.is_total(t)) {
          element_source(t, first, count, sum);
          return;
        }
        std::fill(sum, sum + n * count, 0.0);
        std::array<double, 10> re{};
        std::array<double, 100> ke{};
        element(t, phi_full, re.data(), ke.data(), kind);
        const int* dof = dofs_.element_dofs(t);
        for (int c = 0; c < count; ++c) {
          const Eigen::VectorXd& per_ampere = src.offset_per_ampere[first + c];
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
              sum[c * n + i] += ke[i * n + j] * per_ampere[dof[j]];
        }
      },
      [&](std::size_t e, const double* sum, std::size_t lo, std::size_t hi) {
        const int* eq = &element_eqs_[share_tet(e) * n];
        for (int i = 0; i < n; ++i)
          if (eq[i] >= 0 && static_cast<std::size_t>(eq[i]) >= lo &&
              static_cast<std::size_t>(eq[i]) < hi)
            for (int c = 0; c < count; ++c)
              out(eq[i], c) += sum[c * n + i];
      });
  return out;
}

} // namespace magfem
