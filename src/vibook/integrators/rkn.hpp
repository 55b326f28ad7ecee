/// \file rkn.hpp
/// \brief Runge–Kutta–Nyström methods for q'' = f(q) = −∇U(q) (Hairer, Nørsett & Wanner,
/// *Solving ODEs I*, §II.14; Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
/// §VI.4.2): the tableau (c, ā, b̄, b), its order conditions by Nyström trees and its
/// symplecticity conditions, evaluated in any number type (120-digit MPFR in vibook verify).
///
/// **The method**, with p = q':
///
///     Q_i = q0 + c_i h p0 + h² Σ_j ā_ij f(Q_j),
///     q1  = q0 + h p0 + h² Σ_i b̄_i f(Q_i),    p1 = p0 + h Σ_i b_i f(Q_i).
///
/// It is a partitioned Runge–Kutta method's stage system written without the momenta stages
/// (prk.hpp solves W = c̃ p0 − h M ∇U(q0 + hW) with M = AÂ; here M = ā and c̃ = c), so
/// PartitionedRkMethod steps it (its RKN constructor).
///
/// **Order conditions by Nyström trees.** The derivatives of the exact solution are sums of
/// elementary differentials f^(m)(q)(u_1, …, u_m) whose arguments u are either the velocity
/// p (order 1) or again such a differential; a tree t is the multiset of its arguments, and
/// ρ(t) = 2 + Σ ρ(u) its order (ρ(f) = 2: q'' = f). With e(p) = 1, e(t) = E(t)/(ρ(t)(ρ(t) − 1))
/// and E(t) = Π_u e(u) for the exact solution, and Φ_i(t) = Π_u φ_i(u), φ_i(p) = c_i,
/// φ_i(t) = Σ_j ā_ij Φ_j(t) for the stages, the method has order p when
///
///     Σ_i b̄_i Φ_i(t) = E(t) / (ρ(t)(ρ(t) − 1))   for ρ(t) ≤ p     (the positions),
///     Σ_i b_i Φ_i(t)  = E(t) / (ρ(t) − 1)          for ρ(t) ≤ p + 1 (the velocities),
///
/// obtained by expanding both sides in h (the same bookkeeping as B-series: the symmetry
/// factors σ(t) appear on both sides and cancel); the elementary differentials of distinct
/// trees are independent, so each condition is necessary. Velocity Verlet (c = (0, 1),
/// ā = [[0, 0], [1/2, 0]], b̄ = (1/2, 0), b = (1/2, 1/2)) satisfies them for p = 2 and fails
/// Σ b̄_i c_i = 1/6 of p = 3.
///
/// **Symplecticity** (Suris 1989; Okunbor & Skeel 1992; HLW Theorem VI.4.7): the method is
/// symplectic when b̄_i = b_i(1 − c_i) and b_i(b̄_j − ā_ij) = b_j(b̄_i − ā_ji) for all i, j.
///
/// Chapter: \ref chapter-verify (section "Runge–Kutta–Nyström tableaus").
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace vibook {

/// A Runge–Kutta–Nyström tableau with entries in T: nodes c, stage matrix ā (abar), weights b̄
/// (bbar) for the positions and b for the velocities, s stages each.
template <class T>
struct RknTableauT {
  std::vector<T> c, bbar, b;
  std::vector<std::vector<T>> abar;
  int stages() const { return static_cast<int>(b.size()); }
};

/// A Nyström tree: its arguments (−1 the velocity p, k ≥ 0 the tree of that index in the list
/// it belongs to), sorted, and its order ρ = 2 + Σ ρ(argument).
struct NystromTree {
  std::vector<int> args;
  int order = 2;
};

/// Every Nyström tree of order 2 … max_order, by increasing order (a tree's arguments come
/// before it): 1, 1, 2, 3, 6, 10, 20, 36, 72 trees of orders 2 … 10 (rkn_test.cpp).
inline std::vector<NystromTree> nystrom_trees(int max_order) {
  std::vector<NystromTree> trees;
  for (int r = 2; r <= max_order; ++r) {
    // the argument kinds with their orders: p (1), then every tree of order at most r − 2
    std::vector<std::pair<int, int>> kinds{{-1, 1}};
    for (std::size_t i = 0; i < trees.size(); ++i)
      if (trees[i].order <= r - 2) kinds.emplace_back(static_cast<int>(i), trees[i].order);
    std::vector<int> current;
    std::function<void(std::size_t, int)> choose = [&](std::size_t from, int left) {
      if (left == 0) {
        trees.push_back({current, r});
        return;
      }
      for (std::size_t k = from; k < kinds.size(); ++k)
        if (kinds[k].second <= left) {
          current.push_back(kinds[k].first);
          choose(k, left - kinds[k].second);
          current.pop_back();
        }
    };
    choose(0, r - 2);
  }
  return trees;
}

/// How a Nyström tree is written: f for a tree without arguments, f'(p), f''(p, f), … (the
/// m-th derivative as f^(m) from m = 4 on).
inline std::string nystrom_tree_name(const std::vector<NystromTree>& trees, std::size_t k) {
  const auto& args = trees[k].args;
  if (args.empty()) return "f";
  const std::size_t m = args.size();
  std::string s = m <= 3 ? "f" + std::string(m, '\'') : "f^(" + std::to_string(m) + ")";
  s += "(";
  for (std::size_t i = 0; i < m; ++i) {
    if (i > 0) s += ", ";
    s += args[i] < 0 ? std::string("p")
                     : nystrom_tree_name(trees, static_cast<std::size_t>(args[i]));
  }
  return s + ")";
}

/// The order conditions of an RKN tableau as a list (index 0 unused, as the compositions'
/// words): value[w] = left − right of condition w, order[w] the order it belongs to (the
/// positions' condition of a tree of order ρ belongs to ρ, the velocities' to ρ − 1), name[w]
/// the tree and which side ("q: f'(p)", "p: f''(p, p)"). Every condition of orders 1 …
/// max_order.
template <class T>
struct RknConditions {
  std::vector<T> value;
  std::vector<int> order;
  std::vector<std::string> name;
};

template <class T>
RknConditions<T> rkn_conditions(const RknTableauT<T>& t, int max_order) {
  const std::size_t s = t.b.size();
  const std::vector<NystromTree> trees = nystrom_trees(max_order + 1);
  std::vector<std::vector<T>> phi;  // Φ_i(t) per tree
  std::vector<T> E;                 // E(t) per tree
  RknConditions<T> r;
  r.value.emplace_back(0);
  r.order.push_back(0);
  r.name.emplace_back();
  for (std::size_t k = 0; k < trees.size(); ++k) {
    const NystromTree& tree = trees[k];
    std::vector<T> ph(s, T(1));
    T e(1);
    for (int u : tree.args) {
      if (u < 0) {
        for (std::size_t i = 0; i < s; ++i) ph[i] *= t.c[i];
        continue;
      }
      const auto a = static_cast<std::size_t>(u);
      const T rho(trees[a].order);
      e *= E[a] / (rho * (rho - T(1)));
      for (std::size_t i = 0; i < s; ++i) {
        T sum(0);
        for (std::size_t j = 0; j < s; ++j) sum += t.abar[i][j] * phi[a][j];
        ph[i] *= sum;
      }
    }
    const T rho(tree.order);
    T pos(0), vel(0);
    for (std::size_t i = 0; i < s; ++i) {
      pos += t.bbar[i] * ph[i];
      vel += t.b[i] * ph[i];
    }
    const std::string name = nystrom_tree_name(trees, k);
    if (tree.order <= max_order) {
      r.value.push_back(T(pos - e / (rho * (rho - T(1)))));
      r.order.push_back(tree.order);
      r.name.push_back("q: " + name);
    }
    if (tree.order - 1 <= max_order) {
      r.value.push_back(T(vel - e / (rho - T(1))));
      r.order.push_back(tree.order - 1);
      r.name.push_back("p: " + name);
    }
    phi.push_back(std::move(ph));
    E.push_back(e);
  }
  return r;
}

/// The two symplecticity conditions' largest residuals: |b̄_i − b_i(1 − c_i)| and
/// |b_i(b̄_j − ā_ij) − b_j(b̄_i − ā_ji)|.
template <class T, class Abs>
std::pair<double, double> rkn_symplectic_residuals(const RknTableauT<T>& t, Abs abs) {
  const std::size_t s = t.b.size();
  double first = 0, second = 0;
  for (std::size_t i = 0; i < s; ++i) {
    first = std::max(first, abs(T(t.bbar[i] - t.b[i] * (T(1) - t.c[i]))));
    for (std::size_t j = 0; j < s; ++j)
      second = std::max(second, abs(T(t.b[i] * (t.bbar[j] - t.abar[i][j]) -
                                      t.b[j] * (t.bbar[i] - t.abar[j][i]))));
  }
  return {first, second};
}

}  // namespace vibook
