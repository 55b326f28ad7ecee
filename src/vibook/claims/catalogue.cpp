// The claims catalogue: one row per claim of ../shared/CLAIMS.md, in its order.
// Titles are short forms; the full statement of each claim is in the book's chapters.
#include "vibook/claims/ledger.hpp"

namespace vibook::claims {

const std::vector<ClaimInfo>& catalogue() {
  static const std::vector<ClaimInfo> rows = {
      // Sharma, Borggaard, Patil, Woolsey 2022 — energy-preserving adaptive VIs
      {"S-DEL", "S", "§2.2 (9)–(18)",
       "Time-marching form reproduces the extended discrete Euler–Lagrange equations"},
      {"S-EQ39", "S", "§4.2 (39)–(41)",
       "Printed Kepler midpoint updates agree with those derived from L_d (25)"},
      {"S-F1", "S", "Fig. 1, e = 0.1", "EpAVI vs AVI: steps, energy error, trajectory error"},
      {"S-F2", "S", "Fig. 2, e = 0.7", "AVI steps larger than EpAVI; energy errors 1e-4 vs 1e-13"},
      {"S-F3", "S", "Fig. 3", "t(a) over one period; mean steps of AVI2 and EpAVI"},
      {"S-F4", "S", "Fig. 4, e = 0.7", "Dependence of energy error and step profile on h0"},
      {"S-EQ29", "S", "§3.3 (28)–(30)",
       "Accumulated discrete-energy error below k·max|E_i − E_{i−1}|"},
      {"S-F5", "S", "Fig. 5", "Extended precision: energy drift shrinks with the solver tolerance"},
      {"S-L1", "S", "§4.1 Lemma 1",
       "EpAVI equals a fixed-Δa VI of the time-transformed Lagrangian"},
      {"S-EQ58", "S", "§4.4 (56)–(66)",
       "Modified equation and Lagrangian of the transformed midpoint VI"},
      // Beyond the paper (issue #3): where EpAVI's energy equation has no admissible root.
      {"S-X-EXIST", "S", "§2.2 (16); Shibberu",
       "EpAVI's energy equation can have no admissible root: where it steps, over e and h0"},
      // Vermeeren 2017 — modified equations for variational integrators
      {"V-EX1", "V", "§2 Example 1",
       "Discrete Lagrangians (a)–(d) generate midpoint, Störmer–Verlet, symplectic Euler"},
      {"V-P1", "V", "Proposition 1",
       "Discrete Euler–Lagrange expression is a consistent discretization"},
      {"V-EX2", "V", "Example 2", "Störmer–Verlet modified equation to h²"},
      {"V-EX3", "V", "Example 3, Fig. 1",
       "Harmonic oscillator: modified equation, period 6 at h = 1, arcsin² form"},
      {"V-L6", "V", "Lemma 6, Def. 6",
       "Midpoint-sum-to-integral coefficients (2^{1−2i} − 1)B_{2i}/(2i)!"},
      {"V-SV2", "V", "§5.1.1 (21)–(23)",
       "Störmer–Verlet L_disc, L_mesh, L_mod,3 and equation (22)"},
      {"V-EX4", "V", "Example 4, Fig. 3",
       "Kepler, Störmer–Verlet h = 0.5: modified orbit and precession"},
      {"V-SV4", "V", "§5.1.2", "Fourth-order L_mod,5 and the h⁴ modified equation"},
      {"V-SE", "V", "§5.2 (24)–(25)",
       "Symplectic Euler L_mod,2 and its Legendre transform H_mod,2"},
      {"V-EX5", "V", "Example 5",
       "Anisotropic oscillator: first-order modified equation depends on J₊"},
      {"V-T16", "V", "Theorem 16",
       "Truncated modified equations satisfy the DEL equations to O(h^{k+1})"},
      // Shen & Sun 2025 — splitting VIs, LRL vector, relativistic Kepler
      {"SS-T2", "SS", "Thms 2–4", "Helmholtz conditions decide variationality"},
      {"SS-P4", "SS", "Props 2, 4", "Kepler invariants and Noether characteristics"},
      {"SS-T6", "SS", "Thm 6", "L^1st generates the splitting composition"},
      {"SS-T7", "SS", "Thm 7", "L^2nd generates the symmetric compositions"},
      {"SS-T8", "SS", "Thm 8", "Relativistic VI (3.20) equals the K-symplectic composition (3.19)"},
      {"SS-T10", "SS", "Thm 10", "Nyström modified-equation coefficients f^[1], f^[2]"},
      {"SS-T11", "SS", "Thm 11", "Symplectic Euler modified Lagrangian to h³"},
      {"SS-F1", "SS", "Fig. 1", "Pendulum: discrete orbit on a level set of H_mod,1"},
      {"SS-T12", "SS", "Thm 12", "Modified Lagrangians and equations of VI-1 and VI-2"},
      {"SS-T13", "SS", "Thms 13–16", "One-period LRL changes from the modified Lagrangians"},
      {"SS-F2", "SS", "Fig. 2", "Kepler e = 0.6 orbits: precession by method"},
      {"SS-F3", "SS", "Fig. 3", "Energy error bounded for all four methods"},
      {"SS-F4", "SS", "Fig. 4", "Eccentricity error; VI-1 and VI-2 smaller"},
      {"SS-F5", "SS", "Fig. 5", "Rotation-angle error; VI-1 and VI-2 smaller"},
      {"SS-F6", "SS", "Fig. 6", "Convergence orders of eccentricity and angle over one period"},
      {"SS-F7", "SS", "Fig. 7", "Relativistic Kepler orbits against the exact precessing orbit"},
      {"SS-AA", "SS", "Appendix A",
       "Central-difference modified equation as a convergent arcsin² series"},
  };
  return rows;
}

}  // namespace vibook::claims
