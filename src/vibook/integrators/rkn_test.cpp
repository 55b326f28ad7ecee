// Doctests for integrators/rkn.hpp: the Nyström trees, the order and symplecticity conditions
// of Runge–Kutta–Nyström tableaus whose answers are known, and the RKN step of
// PartitionedRkMethod against the velocity Verlet step written out.
#include "vibook/integrators/rkn.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "vibook/integrators/prk.hpp"
#include "vibook/problems/problems.hpp"

using namespace vibook;

namespace {

// The order the conditions give: the largest p with every condition of orders 1 … p within
// `tol` (1e-13 here: the tableaus below are exact ratios, rounded to double once).
int order_of(const RknTableauT<double>& t, int max_order, double tol = 1e-13) {
  const RknConditions<double> rc = rkn_conditions(t, max_order);
  std::vector<double> worst(static_cast<std::size_t>(max_order + 1), 0.0);
  for (std::size_t w = 1; w < rc.value.size(); ++w) {
    auto& x = worst[static_cast<std::size_t>(rc.order[w])];
    x = std::max(x, std::abs(rc.value[w]));
  }
  int p = 0;
  while (p < max_order && worst[static_cast<std::size_t>(p + 1)] <= tol) ++p;
  return p;
}

RknTableauT<double> velocity_verlet() { return {{0, 1}, {0.5, 0}, {0.5, 0.5}, {{0, 0}, {0.5, 0}}}; }

// Hairer, Nørsett & Wanner I, §II.14: explicit, four stages, order 5 for q'' = f(q).
RknTableauT<double> hnw5() {
  return {{0, 1.0 / 5, 2.0 / 3, 1},
          {14.0 / 336, 100.0 / 336, 54.0 / 336, 0},
          {14.0 / 336, 125.0 / 336, 162.0 / 336, 35.0 / 336},
          {{0, 0, 0, 0},
           {1.0 / 50, 0, 0, 0},
           {-1.0 / 27, 7.0 / 27, 0, 0},
           {3.0 / 10, -2.0 / 35, 9.0 / 35, 0}}};
}

}  // namespace

TEST_CASE("Nystrom trees: 1, 1, 2, 3, 6, 10, 20, 36, 72 of orders 2 to 10") {
  // Counted by hand up to order 6: f; f'(p); f''(p, p), f'(f); f'''(p, p, p), f''(p, f),
  // f'(f'(p)); and of order 6 f^(4)(p, p, p, p), f'''(p, p, f), f''(f, f), f''(p, f'(p)),
  // f'(f''(p, p)), f'(f'(f)). A tree left out or counted twice changes the counts.
  const std::vector<NystromTree> t = nystrom_trees(10);
  std::vector<int> count(11, 0);
  for (const auto& x : t) ++count[static_cast<std::size_t>(x.order)];
  CHECK(count == std::vector<int>{0, 0, 1, 1, 2, 3, 6, 10, 20, 36, 72});
  // trees are listed after their arguments, and named by them
  CHECK(nystrom_tree_name(t, 0) == "f");
  CHECK(nystrom_tree_name(t, 1) == "f'(p)");
  CHECK(nystrom_tree_name(t, 2) == "f''(p, p)");
  CHECK(nystrom_tree_name(t, 3) == "f'(f)");
}

TEST_CASE("RKN order conditions: velocity Verlet 2, HNW's explicit method 5, its corruption 2") {
  CHECK(order_of(velocity_verlet(), 8) == 2);
  CHECK(order_of(hnw5(), 8) == 5);
  // three coefficients changed with the sums kept: abar_32, bbar_1, bbar_2
  RknTableauT<double> w = hnw5();
  w.abar[2][1] = 8.0 / 27;
  w.bbar[0] = 4.0 / 336;
  w.bbar[1] = 110.0 / 336;
  CHECK(order_of(w, 8) == 2);
  // Gauss collocation with 2 stages as an RKN tableau: abar = A², bbar = bᵀA, order 4
  const double r = std::sqrt(3.0) / 6;
  const double a[2][2] = {{0.25, 0.25 - r}, {0.25 + r, 0.25}};
  RknTableauT<double> g{{0.5 - r, 0.5 + r}, {0, 0}, {0.5, 0.5}, {{0, 0}, {0, 0}}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      g.abar[i][j] = a[i][0] * a[0][j] + a[i][1] * a[1][j];
      g.bbar[j] += 0.5 * a[i][j];
    }
  CHECK(order_of(g, 8) == 4);
}

TEST_CASE("RKN symplecticity conditions: velocity Verlet and Gauss hold, HNW's explicit 5 fails") {
  auto abs = [](double x) { return std::abs(x); };
  const auto vv = rkn_symplectic_residuals(velocity_verlet(), abs);
  CHECK(vv.first == 0.0);
  CHECK(vv.second == 0.0);
  const auto h5 = rkn_symplectic_residuals(hnw5(), abs);
  CHECK(h5.first <= 1e-16);  // bbar = b (1 - c) holds for it
  CHECK(h5.second > 1e-2);   // the second condition does not
}

TEST_CASE("RKN step: velocity Verlet's tableau is the velocity Verlet step") {
  PartitionedRkMethod<Eigen::Dynamic, Pendulum> m(Pendulum{}, velocity_verlet());
  Vec<double, 1> q{1.0}, p{0.5};
  const double h = 0.1;
  // by hand: p_{1/2} = p0 - h/2 sin q0, q1 = q0 + h p_{1/2}, p1 = p_{1/2} - h/2 sin q1
  const double ph = 0.5 - 0.05 * std::sin(1.0), q1 = 1.0 + h * ph, p1 = ph - 0.05 * std::sin(q1);
  m.step(q, p, h);
  CHECK(std::abs(q(0) - q1) <= 4e-16);
  CHECK(std::abs(p(0) - p1) <= 4e-16);
  CHECK(std::isnan(m.action()));
}
