// The claims catalogue: one row per claim of ../shared/CLAIMS.md, in its order.
// Titles are short forms; the full statement of each claim is in the book's chapters.
#include "vibook/claims/ledger.hpp"
#include "vibook/verify/field_audit.hpp"

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
  // The field audit (issue #25): one claim per published composition, the method's source as
  // its "paper", and one per deliberately wrong composition (verify/field_audit.hpp).
  static const std::vector<ClaimInfo> all = [] {
    std::vector<ClaimInfo> r = rows;
    for (const auto& a : verify::audit_entries()) r.push_back(a.info);
    return r;
  }();
  return all;
}

std::string_view paper_statement(std::string_view id) {
  // The claim as ../shared/CLAIMS.md states it, with the paper's numbers and, where the paper
  // leaves a choice, what we decided to measure. The report prints it beside our measurement.
  static const std::vector<std::pair<std::string_view, std::string_view>> rows = {
      {"S-DEL",
       "For an extended discrete Lagrangian, the time-marching form (15)–(18) reproduces the "
       "two-step extended discrete Euler–Lagrange equations (11)–(12); discrete momentum (13) and "
       "energy (14). Check on Kepler and a 1-DOF oscillator."},
      {"S-EQ39",
       "The printed Kepler midpoint update equations agree with those derived from L_d (25). "
       "Derive with automatic differentiation and compare term by term."},
      {"S-F1",
       "(a) EpAVI and AVI1 give nearly the same time steps, AVI2 marginally larger; (b) AVI1/AVI2 "
       "energy error about 1e-7, EpAVI about 1e-14; (c) q1, q2 trajectory errors about equal, "
       "EpAVI marginally better, slow linear growth (Remark 2)."},
      {"S-F2",
       "AVI steps significantly larger than EpAVI; steps grow 12–15× h0; AVI energy error about "
       "1e-4, EpAVI about 1e-13; trajectory errors as in S-F1."},
      {"S-F3",
       "Mean step: e = 0.1 — AVI2 1.23 h0, EpAVI 1.17 h0; e = 0.7 — AVI2 7.93 h0, EpAVI 6.22 h0; 0 "
       "< t'(a) ≤ const."},
      {"S-F4",
       "AVI2 energy error grows with h0; EpAVI's changes little (the text's direction is "
       "self-contradictory: measure and say which holds); h_k/h0 profile nearly independent of "
       "h0."},
      {"S-EQ29",
       "The accumulated discrete-energy error stays below the bound k·max_i |E_i − E_{i−1}|; "
       "measure how far below, over at least 1e6 steps."},
      {"S-F5",
       "With 18 significant digits (the paper's VPA), the discrete-energy drift shrinks as the "
       "solver tolerance falls, reaching exact conservation up to precision at tolerance 1e-17; "
       "the step profile is unchanged."},
      {"S-L1",
       "EpAVI equals a fixed-Δa variational integrator of the time-transformed Lagrangian (31) "
       "with discrete Lagrangian (35)."},
      {"S-EQ58",
       "Midpoint discretization of a 1-DOF mechanical system in the transformed setting: L̄_disc "
       "(58), L̄_mesh (59), modified Euler–Lagrange (60)–(62), modified equation (63), modified "
       "Lagrangian (64), its Euler–Lagrange equation (65)–(66). Derive each and compare with the "
       "print."},
      {"S-X-EXIST",
       "Not a claim of the paper but a question it leaves open (Shibberu): for which "
       "eccentricities e and initial steps h0 the "
       "energy equation (16) has an admissible root, so that EpAVI can step at all."},
      {"V-EX1",
       "The discrete Lagrangians generate the implicit midpoint rule, Störmer–Verlet, and the two "
       "symplectic Euler methods through the discrete Legendre maps (5)."},
      {"V-P1",
       "The discrete Euler–Lagrange expression is a consistent discretization of the continuous "
       "one (measured order)."},
      {"V-EX2", "Störmer–Verlet modified equation to h²."},
      {"V-EX3",
       "Harmonic oscillator: modified equation −x − h²x/12 − h⁴x/90; with h = 1 the discrete "
       "solution is periodic with period 6; the exact modified equation −(2/h·arcsin(h/2))² x; the "
       "arcsin² series; Fig. 1 (h = 1, x0 = 1, x1 = exact x(1); order-2 and order-4 truncations, "
       "zoom on [80, 100])."},
      {"V-L6",
       "Midpoint-sum-to-integral coefficients (2^{1−2i} − 1)B_{2i}/(2i)!: −1/24, 7/5760, …"},
      {"V-SV2",
       "L_disc, L_mesh, L_mod,3 for Störmer–Verlet on a mechanical Lagrangian; the Euler–Lagrange "
       "equation of L_mod,3 solved for ẍ gives (22) up to O(h⁴)."},
      {"V-EX4",
       "Kepler, Störmer–Verlet, h = 0.5, x0 = (−3, 0), ẋ0 = (0, 0.4): L_mod,3 and the modified "
       "equation (coefficients h²/6, −h²/2, −h²/4, 5h²/4); the modified orbit precesses "
       "counterclockwise while the body moves clockwise, marginally slower than the discrete orbit "
       "(measure both precession rates)."},
      {"V-SV4", "Fourth-order L_disc, L_mesh, L_mod,5 and the h⁴ modified equation."},
      {"V-SE", "Symplectic Euler: L_mod,2, and its Legendre transform equals H_mod,2 up to O(h³)."},
      {"V-EX5",
       "Anisotropic (non-separable) oscillator: first-order modified equation −(h/2)M⁻¹J₊M⁻¹(J₋ẋ + "
       "Ax) depends on J₊."},
      {"V-T16",
       "For several discrete Lagrangians and k ≥ 2: solutions of the k-th truncated modified "
       "equation satisfy the discrete Euler–Lagrange equations with defect O(h^{k+1}) (measured "
       "order)."},
      {"SS-T2",
       "Helmholtz conditions decide whether d/dt(M ẋ) = f is variational: true for Kepler, for the "
       "relativistic system (2.7), for a Lorentz-type force with antisymmetric A; false for a "
       "damped oscillator."},
      {"SS-P4",
       "Kepler invariants H, m, A, and the Noether characteristics v_H, v_m, v_A1, v_A2 (dP/dt = "
       "N[x]·Q)."},
      {"SS-T6",
       "The discrete Euler–Lagrange equations of L^1st (any potential splitting) equal the "
       "composition Φ_{H_N} ∘ … ∘ Φ_{H_1}."},
      {"SS-T7", "L^2nd generates Φ*_{h/2} ∘ Φ_{h/2} and Φ_{h/2} ∘ Φ*_{h/2}."},
      {"SS-T8",
       "The relativistic variational integrator (3.20) equals the K-symplectic composition "
       "(3.19)."},
      {"SS-T10", "Nyström-method modified-equation coefficients f^[1], f^[2]."},
      {"SS-T11", "Symplectic Euler modified Lagrangian to h³ and its Euler–Lagrange equation."},
      {"SS-F1",
       "Pendulum φ = cos x, symplectic Euler, (x0, v0, h) = (π/2, 0.5, 0.25): the discrete orbit "
       "lies on a level set of H_mod,1 far more closely than on one of H."},
      {"SS-T12", "Modified Lagrangians and modified equations of VI-1 and VI-2."},
      {"SS-T13",
       "One-period LRL changes from the modified Lagrangians: Störmer–Verlet eccentricity error "
       "O(h⁴); symplectic Euler and VI-1 errors O(h²); the period averages that vanish."},
      {"SS-F2",
       "Kepler e = 0.6, h = 0.05, t ∈ [0, 200]: symplectic Euler and Störmer–Verlet orbits drift "
       "(precess) visibly; VI-1 and VI-2 less; VI-2 least."},
      {"SS-F3", "Energy error bounded for all four methods."},
      {"SS-F4", "Eccentricity error bounded; VI-1 and VI-2 significantly smaller."},
      {"SS-F5", "Rotation-angle error; VI-1 and VI-2 significantly smaller."},
      {"SS-F6",
       "Over one period — eccentricity: symplectic Euler and VI-1 order 2 (nearly identical), "
       "Störmer–Verlet order 4, VI-2 super-convergent and below Störmer–Verlet; angle: all order "
       "2, symplectic Euler ≈ Störmer–Verlet, VI-1 and VI-2 smaller, VI-2 smallest. Measure the "
       "orders; say which initial condition and how the period is closed."},
      {"SS-F7",
       "Relativistic Kepler with (3.20) and the second-order splitting: orbits against the exact "
       "(precessing) orbit. The speed of light is not given: choose, state, and sweep it."},
      {"SS-AA",
       "Central-difference modified equation of the harmonic oscillator as a convergent arcsin² "
       "series, with its radius of convergence."},
  };
  for (const auto& [key, text] : rows)
    if (key == id) return text;
  for (const auto& a : verify::audit_entries())
    if (a.info.id == id) return a.statement;
  return {};
}

}  // namespace vibook::claims
