#include "model/linear_shell.h"

#include <Eigen/Geometry>
#include <stdexcept>

#include "element/quadrature.h"

namespace vs::shell3d {

LinearShellProblem::LinearShellProblem(const ShellModel& model, const Shell9Material& material,
                                       const LinearShellOptions& options)
    : model_(&model),
      material_(material),
      options_(options),
      asm_(model),
      solver_(options.solver),
      f_(Eigen::VectorXd::Zero(model.num_dofs())) {
  if (options_.thickness.zeta.empty())
    options_.thickness = thickness_rule(ThicknessKind::kGauss, 2);
}

void LinearShellProblem::add_point_load(int node, const Vec3& force) {
  for (int k = 0; k < 3; ++k) f_(model_->dof(node, k)) += force(k);
}

void LinearShellProblem::add_surface_load(const Vec3& traction) {
  const Rule1D g = gauss_legendre(3);
  const ShellMesh& m = model_->mesh();
  for (int e = 0; e < m.num_elements(); ++e) {
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        const Shape9 sh = lagrange9(g.x[i], g.x[j]);
        Vec3 gr = Vec3::Zero(), gs = Vec3::Zero();
        for (int a = 0; a < 9; ++a) {
          gr += sh.dr(a) * m.nodes[m.elements[e][a]];
          gs += sh.ds(a) * m.nodes[m.elements[e][a]];
        }
        const double dA = gr.cross(gs).norm() * g.w[i] * g.w[j];
        for (int a = 0; a < 9; ++a) add_point_load(m.elements[e][a], (sh.N(a) * dA) * traction);
      }
  }
}

ElementKernel LinearShellProblem::kernel(Shell9Stiffness kind) const {
  return [this, kind](int e, const Eigen::VectorXd& qe, ElementContribution* c) {
    const Shell9Geometry g = model_->element_geometry(e);
    Shell9Output out;
    shell9_evaluate(g, options_.rule, options_.thickness, material_, Shell9State{}, qe, kind, &out);
    c->force = std::move(out.force);
    c->stiffness = std::move(out.stiffness);
    c->potential = out.potential;
  };
}

Eigen::VectorXd LinearShellProblem::solve() {
  const int n = model_->num_dofs();
  Eigen::VectorXd zero = Eigen::VectorXd::Zero(n), r;
  asm_.assemble(kernel(Shell9Stiffness::kSecant), zero, true, &r);
  Eigen::VectorXd rhs = f_;
  asm_.apply_constraints(model_->fixed(), model_->fixed_value(), &rhs);
  if (!analyzed_) {
    solver_.analyze(asm_.matrix());
    analyzed_ = true;
  }
  if (!solver_.factorize(asm_.matrix()))
    throw std::runtime_error("LinearShellProblem: factorisation failed (singular model?)");
  return solver_.solve(rhs);
}

Vec3 LinearShellProblem::translation(const Eigen::VectorXd& q, int node) const {
  return Vec3(q(model_->dof(node, 0)), q(model_->dof(node, 1)), q(model_->dof(node, 2)));
}

}  // namespace vs::shell3d
