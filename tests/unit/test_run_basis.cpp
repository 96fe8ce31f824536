// The run modes in closed form (run_basis.cpp) against the stiffness matrix they diagonalise
// (run_stiffness.hpp) and against Eigen's symmetric eigensolver, for every kind of end and for
// lengths from one block to a long groove: K Q = Q diag(lambda) and Q^T Q = I to round-off, and
// the same eigenvalues, in the same rising order, as the solver gives.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

#include "springblock/integrate/linear/run_basis.hpp"
#include "springblock/integrate/linear/run_stiffness.hpp"

namespace {

using sb::event_detail::run_stiffness;
using sb::event_detail::RunBases;

sb::Chain chain() {
  sb::Chain c;
  c.N = 400;
  c.K_s = 1.0e4, c.K_int = 7.48e5, c.m = 2.4e-6, c.gamma = 1.0e4;
  return c;
}

TEST(RunBasis, ClosedFormDiagonalisesEveryShape) {
  const sb::Chain c = chain();
  RunBases bases(c);
  for (int n : {1, 2, 3, 5, 10, 17, 32, 64, 150})
    for (bool left : {false, true})
      for (bool right : {false, true}) {
        SCOPED_TRACE("n = " + std::to_string(n) + " left " + std::to_string(left) + " right " + std::to_string(right));
        const auto& b = bases.get(n, left, right);
        const Eigen::MatrixXd K = run_stiffness(c.K_s, c.K_int, n, left, right);
        const double scale = c.K_s + 4.0 * c.K_int;
        const Eigen::MatrixXd residual = K * b.Q - b.Q * b.lambda.asDiagonal();
        EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-13 * scale);
        const Eigen::MatrixXd gram = b.Q.transpose() * b.Q - Eigen::MatrixXd::Identity(n, n);
        EXPECT_LT(gram.cwiseAbs().maxCoeff(), 1e-13);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K);
        for (int k = 0; k < n; ++k) EXPECT_NEAR(b.lambda[k], es.eigenvalues()[k], 1e-13 * scale) << "mode " << k;
        // The mode shapes the quiet phase and the modal runs read by row.
        for (int k = 0; k < n; ++k) {
          EXPECT_EQ(b.first_row[k], b.Q(0, k));
          EXPECT_EQ(b.last_row[k], b.Q(n - 1, k));
        }
      }
}

// A wrong boundary (a held end treated as free) leaves a residual the test above sees.
TEST(RunBasis, TheResidualTestSeesAWrongEnd) {
  const sb::Chain c = chain();
  RunBases bases(c);
  const auto& b = bases.get(10, true, false);
  const Eigen::MatrixXd K = run_stiffness(c.K_s, c.K_int, 10, true, true);
  const Eigen::MatrixXd residual = K * b.Q - b.Q * b.lambda.asDiagonal();
  EXPECT_GT(residual.cwiseAbs().maxCoeff(), 1e-3 * c.K_int);
}

}  // namespace
