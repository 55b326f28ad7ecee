// Doctests of constrained.hpp and of the constrained phases of the map study (chapter "Verify
// your own integrator", section "Constrained systems"): RATTLE passes on a constrained test
// problem; without its velocity projection it fails the hidden constraint; symplecticity on the
// constraint manifold passes the exact flow of a free particle on the sphere and fails a
// projected explicit Euler.
#include "vibook/verify/constrained.hpp"

#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>

#include "vibook/verify/phases.hpp"

using namespace vibook;
using namespace vibook::verify;

namespace {

bool failed(const MapMeasurement& r, const std::string& part) {
  return std::find(r.failed.begin(), r.failed.end(), part) != r.failed.end();
}

MapMeasurement rattle(const std::string& name, bool project) {
  const ConstrainedProblem* p = find_constrained_problem(name);
  REQUIRE(p != nullptr);
  MapStudy s;
  s.steps = 4096;
  MapMeasurement r;
  measure_constrained(*p, project, p->q0, p->p0, s, r);
  return r;
}

// The tangent space of T*S² at z = (q, p): the kernel of (q, 0) and (p, q), orthonormal.
Eigen::MatrixXd sphere_tangent(const Eigen::VectorXd& z) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2, 6);
  C.block(0, 0, 1, 3) = z.head(3).transpose();
  C.block(1, 0, 1, 3) = z.tail(3).transpose();
  C.block(1, 3, 1, 3) = z.head(3).transpose();
  const Eigen::MatrixXd K = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(K);
  return qr.householderQ() * Eigen::MatrixXd::Identity(6, K.cols());
}

Eigen::VectorXd sphere_state() {
  Eigen::VectorXd z(6);
  z << std::sin(1.0), 0, -std::cos(1.0), 0, 0.8, 0;
  return z;
}

}  // namespace

// Each problem and each method once here, through the library's call: RATTLE on the spherical
// pendulum, the unprojected method on the double pendulum. The other two pairs (RATTLE on the
// double pendulum, the unprojected method on the spherical one) are the book's examples, checked
// by tests/cli/book_examples.sh, through the same measure_constrained.
TEST_CASE(
    "RATTLE on the spherical pendulum, and without the velocity projection it fails on the double "
    "pendulum") {
  const MapMeasurement right = rattle("spherical-pendulum", true);
  CHECK(right.failed.empty());
  CHECK(std::abs(right.js["order"]["fitted"].get<double>() - 2) < 0.2);
  const MapMeasurement wrong = rattle("double-pendulum", false);
  CHECK(failed(wrong, "hidden constraint"));
  CHECK_FALSE(failed(wrong, "position constraint"));
}

TEST_CASE(
    "symplecticity on the constraint manifold: the exact flow passes, projected Euler fails") {
  // A free particle on the unit sphere moves on great circles: the exact flow of H = |p|²/2 on
  // T*S², a symplectic map of the manifold (the edge: it is defined on the manifold only; the
  // normalisation below extends it off the manifold, where its Jacobian says nothing).
  const Step exact = [](Eigen::VectorXd& z, double h) {
    const Eigen::Vector3d q = z.head(3), p = z.tail(3);
    // the flow of the constrained free particle, extended off the manifold by normalising
    const double r = q.norm();
    const Eigen::Vector3d e = q / r, v = p - e * e.dot(p);
    const double w = v.norm();
    const Eigen::Vector3d u = v / w;
    z.head(3) = e * std::cos(w * h) + u * std::sin(w * h);
    z.tail(3) = w * (-e * std::sin(w * h) + u * std::cos(w * h));
  };
  // Explicit Euler on the free particle, then q projected radially onto the sphere and p onto
  // the tangent plane there: first order, not symplectic.
  const Step projected_euler = [](Eigen::VectorXd& z, double h) {
    Eigen::Vector3d q = z.head(3) + h * z.tail(3);
    q /= q.norm();
    Eigen::Vector3d p = z.tail(3) - h * 0.5 * z.head(3);  // a radial "force", then projected
    p -= q * q.dot(p);
    z.head(3) = q;
    z.tail(3) = p;
  };
  const std::vector<Eigen::VectorXd> states{sphere_state()};
  const ScalingJudgement ok =
      symplecticity_by_scaling(exact, states, 0.05, kScalingSizes, sphere_tangent);
  CHECK(ok.passed);
  const ScalingJudgement no =
      symplecticity_by_scaling(projected_euler, states, 0.05, kScalingSizes, sphere_tangent);
  CHECK_FALSE(no.passed);
}
