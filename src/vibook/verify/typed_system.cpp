// The typed system's reference field and energy (typed_system.hpp), compiled once for each
// dimension 1..kMaxDim: every typed route of `vibook verify` (--ld, --hamiltonian with a
// black box, --composition on a typed L_d, --method and --tableau on --potential) uses them.
#include "vibook/verify/typed_system.hpp"

#include <vector>

namespace vibook::verify {

template <int N>
Field<dd_real> typed_hamilton_field(const TypedDiscreteLagrangian& sys) {
  return [&sys](const std::vector<dd_real>& y) {
    Vec<dd_real, N> q, pp;
    for (int i = 0; i < N; ++i) {
      q(i) = y[static_cast<std::size_t>(i)];
      pp(i) = y[static_cast<std::size_t>(N + i)];
    }
    const Vec<dd_real, 2 * N> f = sys.hamilton_field<N, dd_real>(q, pp);
    return std::vector<dd_real>(f.data(), f.data() + 2 * N);
  };
}

template <int N>
void set_typed_system(MapStudy& s, const TypedDiscreteLagrangian& sys, const Eigen::VectorXd& z0) {
  s.z0 = z0;
  s.field = typed_hamilton_field<N>(sys);
  s.equations = "Hamilton's equations of H";
  s.H = [&sys](const Eigen::VectorXd& z) {
    return sys.hamiltonian<N, double>(Vec<double, N>(z.head<N>()), Vec<double, N>(z.tail<N>()));
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
