// The dual norm of a plane-stress yield function by a local Newton solve, for criteria whose dual
// has no closed form (Yld2000-2d). Notation of plane_stress_yield.h.
//
// Problem. Given a rate d != 0, find the stress m on the unit yield surface (sigma_bar(m) = 1)
// whose normal is parallel to d (normality d = lambda dsigma_bar/ds (m), lambda > 0). Then
// e(d) = lambda = m . d (Euler: s . dsigma_bar/ds = sigma_bar for a degree-one function).
//
// Formulation. Sigma(s) = sigma_bar(s)^2 / 2 is convex and homogeneous of degree two; its gradient
// sigma_bar n (n = dsigma_bar/ds) is homogeneous of degree one and its Hessian
//   K(s) = n n^T + sigma_bar d^2sigma_bar/ds^2
// of degree zero. K is positive definite for a strictly convex, smooth yield surface: the Hessian
// of sigma_bar is positive semi-definite with the single null direction s, and n . s =
// sigma_bar > 0. The stationary point of the strictly convex function
//   J(s) = Sigma(s) - dhat . s,      dhat = d / |d|,
// solves sigma_bar(s) n(s) = dhat: n(s*) is parallel to d, and s* . dhat = sigma_bar(s*)^2, so
// e(dhat) = sigma_bar(s*) and m = s* / sigma_bar(s*). Newton on grad J = 0 with the matrix K and a
// backtracking (Armijo) line search on J converges from any start (J is convex with K bounded and
// positive definite on the unit sphere); near the solution the convergence is quadratic. Working
// with the unit dhat makes the iteration independent of the magnitude of d, so near-rigid points
// (d -> 0) cost the same as plastic ones. Start: the warm-start direction m0 if given, else the von
// Mises dual of dhat (s0 ~ [[4,2,0],[2,4,0],[0,0,1]] dhat), each scaled along its ray to the
// minimum of J (c = dhat . s0 / sigma_bar(s0)^2).
//
// Derivatives for the consistent tangent. With g(d) = e m = dE/dd (E = e^2/2, the Legendre
// conjugate of Sigma), g solves dSigma/ds (g) = d; differentiating, K(g) dg = dd, so
//   H(d) = d^2E/dd^2 = K(g)^-1 = K(s*)^-1         (K has degree zero: K(g) = K(s*)),
// the inverse of the Newton matrix at convergence: no second solve and no bordered system.
// For Hill 1948 (Sigma = s^T P s / 2) this gives H = P^-1, its closed form (tested).
#pragma once

#include "material/plane_stress_yield.h"

namespace vs {

struct DualSolveOptions {
  // Converged when |sigma_bar(s) n(s) - dhat| <= tolerance (dhat is a unit vector).
  double tolerance = 1e-12;
  int max_iterations = 50;
};

// The dual point of `yield` at d (material axes); guess: optional unit-surface stress (warm start;
// also fixes the direction of H at d = 0, see PlaneStressYield::dual).
DualPoint solve_dual(const PlaneStressYield& yield, const PlaneVector& d,
                     const PlaneVector* guess = nullptr, const DualSolveOptions& options = {});

}  // namespace vs
