// Linear (constant-viscosity / linear elastic) solve of a shell model: K q = f with point loads
// and consistent surface loads, the model's constraints imposed on the fixed pattern. This is
// the viscous element at a fixed viscosity (mu = G), used for the elastic benchmarks
// (numerics.md 1.1, 1.3-1.4) and as the first Picard iterate of the forming solver.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "element/shell9.h"
#include "linalg/sparse_spd_solver.h"
#include "model/shell_assembler.h"

namespace vs::shell3d {

struct LinearShellOptions {
  Shell9Rule rule = Shell9Rule::kMitc9;
  ThicknessRule thickness;  // empty = 2-point Gauss
  SparseSolverKind solver = SparseSolverKind::kCholmodSupernodal;
};

class LinearShellProblem {
 public:
  LinearShellProblem(const ShellModel& model, const Shell9Material& material,
                     const LinearShellOptions& options = {});

  void add_point_load(int node, const Vec3& force);
  // Uniform load per unit mid-surface area (e.g. self weight), lumped consistently (3x3 Gauss).
  void add_surface_load(const Vec3& traction);
  const Eigen::VectorXd& load() const { return f_; }

  // Solves and returns the global velocity (displacement) vector.
  Eigen::VectorXd solve();
  Vec3 translation(const Eigen::VectorXd& q, int node) const;

  ShellAssembler& assembler() { return asm_; }
  const SparseSpdSolver& solver() const { return solver_; }
  ElementKernel kernel(Shell9Stiffness kind) const;

 private:
  const ShellModel* model_;
  Shell9Material material_;
  LinearShellOptions options_;
  ShellAssembler asm_;
  SparseSpdSolver solver_;
  Eigen::VectorXd f_;
  bool analyzed_ = false;
};

}  // namespace vs::shell3d
