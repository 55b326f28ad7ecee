// The Galerkin variational integrators of method_study.cpp in double-double, on the test
// problems: the nodes and weights refined in double-double (quadrature_in), the step solved to
// double-double's round-off, and the step's discrete Lagrangian beside it. With them the order
// study and the variational order of a method of order 6 or more run where double's round-off
// cannot hide the asymptotic range (MapStudy::step_dd, MapStudy::generating_dd; chapter "Verify
// your own integrator", section "Orders beyond double"). Its own unit: the nested AutoDiff
// over double-double is the expensive part to compile.
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "vibook/kepler/kepler.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/verify/method_study_impl.hpp"

namespace vibook::verify::method_detail {

namespace {

template <class P>
GalerkinDD galerkin_dd_for(const P& prob, const Quadrature& rule) {
  constexpr int N = P::N;
  auto L = mechanical_lagrangian_of(prob);
  using Integrator = GalerkinIntegrator<N, Eigen::Dynamic, decltype(L), dd_real>;
  const QuadratureT<dd_real> r = quadrature_in<dd_real>(rule);
  auto steps = dd_steps<N>([&] { return std::make_shared<Integrator>(L, r); });
  return {std::move(steps.first), std::move(steps.second)};
}

}  // namespace

GalerkinDD galerkin_dd(const std::string& problem, const Quadrature& rule) {
  if (rule.c.empty() || rule.c.size() > 5)
    throw std::invalid_argument("galerkin_dd: 1 to 5 stages");
  if (problem == "pendulum") return galerkin_dd_for(Pendulum{}, rule);
  if (problem == "henon-heiles") return galerkin_dd_for(HenonHeiles{}, rule);
  if (problem == "kepler") return galerkin_dd_for(Kepler{}, rule);
  throw std::invalid_argument("galerkin_dd: no test problem '" + problem + "'");
}

}  // namespace vibook::verify::method_detail
