/// \file typed_lagrangian_study.cpp
/// \brief The intended system of a catalogue route given as a typed Lagrangian L(q, v)
/// (`vibook verify --method --lagrangian`, `--composition ld --lagrangian`), set into a map study
/// (typed_system.hpp) through its Legendre transform: the reference, the energy and the initial
/// state, with the report line naming the system. The templates are typed_lagrangian_impl.hpp;
/// three degrees of freedom compile in typed_lagrangian_3.cpp. The potential and Hamiltonian
/// forms are in typed_system_study.cpp.
#include "vibook/verify/typed_lagrangian_impl.hpp"

namespace vibook::verify {

namespace typed_lagrangian_detail {
extern template void set_lagrangian_system<3>(MapStudy&, const verify::TypedDiscreteLagrangian&,
                                              const std::vector<double>&,
                                              const std::vector<double>&);
}  // namespace typed_lagrangian_detail

std::string set_typed_lagrangian(MapStudy& s, const verify::TypedDiscreteLagrangian& sys,
                                 const std::string& lagrangian, const std::vector<double>& q0,
                                 const std::vector<double>& p0) {
  using typed_lagrangian_detail::set_lagrangian_system;
  const int n = sys.dim();
  if (n == 1) set_lagrangian_system<1>(s, sys, q0, p0);
  if (n == 2) set_lagrangian_system<2>(s, sys, q0, p0);
  if (n == 3) set_lagrangian_system<3>(s, sys, q0, p0);
  return fmt::format(
      "L = {} (--lagrangian), {} degree{} of freedom, energy H = p.v - L(q, v); q0 = {}, "
      "p0 = {} (p = dL/dv)",
      lagrangian, n, n == 1 ? "" : "s", vec_text(q0), vec_text(p0));
}

}  // namespace vibook::verify
