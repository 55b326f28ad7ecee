/// \file typed_system_study.cpp
/// \brief The intended system of a catalogue route (`vibook verify --method`, `--tableau`,
/// `--composition ld`) from a typed potential or Hamiltonian, set into a map study
/// (typed_system.hpp): the reference, the energy and the initial state, with the report line
/// naming the system. A typed Lagrangian: typed_lagrangian_study.cpp (a unit of its own, so that
/// the two compile in parallel: together they took over a minute).
#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/verify/typed_system.hpp"

namespace vibook::verify {

namespace {

template <int N>
void set_potential_system(MapStudy& s, const verify::TypedDiscreteLagrangian& sys,
                          const std::vector<double>& q0, const std::vector<double>& p0) {
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = q0[static_cast<std::size_t>(i)];
    z0(N + i) = p0[static_cast<std::size_t>(i)];
  }
  set_typed_system<N>(s, sys, z0);
}

}  // namespace

void set_typed_system(MapStudy& s, const TypedDiscreteLagrangian& sys,
                      const std::vector<double>& q0, const std::vector<double>& p0) {
  with_dim(sys.dim(), [&](auto n) { set_potential_system<decltype(n)::value>(s, sys, q0, p0); });
}

std::string set_typed_potential(MapStudy& s, const verify::TypedDiscreteLagrangian& sys,
                                const std::string& potential, const std::vector<double>& q0,
                                const std::vector<double>& p0) {
  const int n = sys.dim();
  set_typed_system(s, sys, q0, p0);
  return fmt::format(
      "H = |p|^2/2 + V(q), V = {} (--potential), {} degree{} of freedom; q0 = {}, "
      "p0 = {}",
      potential, n, n == 1 ? "" : "s", vec_text(q0), vec_text(p0));
}

std::string set_typed_hamiltonian(MapStudy& s, const verify::TypedDiscreteLagrangian& sys,
                                  const std::string& hamiltonian, const std::vector<double>& q0,
                                  const std::vector<double>& p0) {
  const int n = sys.dim();
  set_typed_system(s, sys, q0, p0);
  return fmt::format("H = {} (--hamiltonian), {} degree{} of freedom; q0 = {}, p0 = {}",
                     hamiltonian, n, n == 1 ? "" : "s", vec_text(q0), vec_text(p0));
}

}  // namespace vibook::verify
