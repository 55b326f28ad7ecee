// The typed system's reference field and energy (typed_system.hpp), compiled once for each
// dimension 1..kMaxDim: every typed route of `vibook verify` (--ld, --hamiltonian with a
// black box, --composition on a typed L_d, --method and --tableau on --potential) uses them.
#include "vibook/verify/typed_system.hpp"

#include <vector>

namespace vibook::verify {

// A time-dependent system's state carries the time last, y = (q, p, t), and t' = 1 (the
// extended phase space: the field is autonomous in it).
template <int N>
Field<dd_real> typed_hamilton_field(const TypedDiscreteLagrangian& sys) {
  const bool timed = sys.time_dependent();
  return [&sys, timed](const std::vector<dd_real>& y) {
    Vec<dd_real, N> q, pp;
    for (int i = 0; i < N; ++i) {
      q(i) = y[static_cast<std::size_t>(i)];
      pp(i) = y[static_cast<std::size_t>(N + i)];
    }
    const dd_real t = timed ? y[2 * N] : dd_real(0.0);
    const Vec<dd_real, 2 * N> f = sys.hamilton_field<N, dd_real>(q, pp, t);
    std::vector<dd_real> r(f.data(), f.data() + 2 * N);
    if (timed) r.emplace_back(1.0);
    return r;
  };
}

template <int N>
void set_typed_system(MapStudy& s, const TypedDiscreteLagrangian& sys, const Eigen::VectorXd& z0) {
  s.z0 = z0;
  s.timed = sys.time_dependent();
  if (s.timed) {  // the clock, from t = 0
    s.z0.conservativeResize(2 * N + 1);
    s.z0(2 * N) = 0;
  }
  s.field = typed_hamilton_field<N>(sys);
  s.equations = s.timed ? "Hamilton's equations of H(q, p, t)" : "Hamilton's equations of H";
  s.H = [&sys](const Eigen::VectorXd& z) {
    const double t = z.size() > 2 * N ? z(2 * N) : 0.0;
    return sys.hamiltonian<N, double>(Vec<double, N>(z.head<N>()), Vec<double, N>(z.segment<N>(N)),
                                      t);
  };
}

#define VIBOOK_TYPED_SYSTEM(N)                                                     \
  template Field<dd_real> typed_hamilton_field<N>(const TypedDiscreteLagrangian&); \
  template void set_typed_system<N>(MapStudy&, const TypedDiscreteLagrangian&,     \
                                    const Eigen::VectorXd&);
VIBOOK_FOR_EACH_DIM(VIBOOK_TYPED_SYSTEM)
#undef VIBOOK_TYPED_SYSTEM

double largest_symmetric_eigenvalue(const Eigen::MatrixXd& H) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

}  // namespace vibook::verify
