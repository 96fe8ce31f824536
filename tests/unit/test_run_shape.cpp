// A run's shape (run_shape.cpp) against the stiffness matrix it stands for, for every kind of
// end and for lengths from one block to a long groove: the closed-form modes diagonalise K
// (K Q = Q diag(lambda), Q^T Q = I, the eigenvalues of Eigen's symmetric solver in the same rising
// order), K's factors invert it, and the affine path's pieces solve their equations. A shape
// built for the wrong ends fails the residual test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "springblock/integrate/linear/general_modes.hpp"
#include "springblock/integrate/linear/run_shape.hpp"
#include "gsl_eigen.hpp"

namespace {

using sb::event_detail::RunShape;
using sb::event_detail::RunShapes;

sb::Chain chain() {
  sb::Chain c;
  c.N = 400;
  c.K_s = 1.0e4, c.K_int = 7.48e5, c.m = 2.4e-6, c.gamma = 1.0e4, c.v_slider = 5e-4;
  return c;
}

// K of a run as written in the model: K_s, one K_int per neighbour that exists, -K_int beside.
Eigen::MatrixXd model_stiffness(const sb::Chain& c, int n, bool left, bool right) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r) {
    K(r, r) = c.K_s + ((r > 0 || left) ? c.K_int : 0.0) + ((r + 1 < n || right) ? c.K_int : 0.0);
    if (r + 1 < n) K(r, r + 1) = K(r + 1, r) = -c.K_int;
  }
  return K;
}

// The dense K of a run's factors.
Eigen::MatrixXd dense(const sb::event_detail::Factors& F) {
  const int n = static_cast<int>(F.diag.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r) {
    K(r, r) = F.diag[r];
    if (r + 1 < n) K(r, r + 1) = K(r + 1, r) = F.off[r];
  }
  return K;
}

Eigen::VectorXd vec(const std::vector<double>& x) { return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size()); }

TEST(RunShape, ModesDiagonaliseEveryShape) {
  const sb::Chain c = chain();
  RunShapes shapes(c);
  for (int n : {1, 2, 3, 5, 10, 17, 32, 64, 150})
    for (bool left : {false, true})
      for (bool right : {false, true}) {
        SCOPED_TRACE("n = " + std::to_string(n) + " left " + std::to_string(left) + " right " + std::to_string(right));
        const RunShape& b = shapes.get(n, left, right);
        const Eigen::MatrixXd K = model_stiffness(c, n, left, right);
        EXPECT_EQ((dense(b.K) - K).cwiseAbs().maxCoeff(), 0.0);
        const double scale = c.K_s + 4.0 * c.K_int;
        const Eigen::MatrixXd residual = K * b.Q - b.Q * vec(b.spectrum.lambda).asDiagonal();
        EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-13 * scale);
        const Eigen::MatrixXd gram = b.Q.transpose() * b.Q - Eigen::MatrixXd::Identity(n, n);
        EXPECT_LT(gram.cwiseAbs().maxCoeff(), 1e-13);
        const auto reference = sbtest::symmetric_eigen(K, Eigen::MatrixXd::Identity(n, n)).values;
        for (int k = 0; k < n; ++k) EXPECT_NEAR(b.spectrum.lambda[k], reference[k], 1e-13 * scale) << "mode " << k;
        // The rows the stores and searches read are Q's rows.
        for (int r = 0; r < n; ++r)
          for (int k = 0; k < n; ++k) ASSERT_EQ(b.row(r)[k], b.Q(r, k));
      }
}

TEST(RunShape, FactorsAndAffinePiecesSolveTheirEquations) {
  const sb::Chain c = chain();
  RunShapes shapes(c);
  for (int n : {1, 2, 7, 64, 150})
    for (bool left : {false, true})
      for (bool right : {false, true}) {
        SCOPED_TRACE("n = " + std::to_string(n) + " left " + std::to_string(left) + " right " + std::to_string(right));
        const RunShape& b = shapes.get(n, left, right);
        const Eigen::MatrixXd K = model_stiffness(c, n, left, right);
        const Eigen::VectorXd f = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
        Eigen::VectorXd y(n);
        b.K.solve(f.data(), y.data());
        EXPECT_LT((K * y - f).cwiseAbs().maxCoeff(), 1e-12 * f.cwiseAbs().maxCoeff());
        // K B = K_s v 1, K a0 = -m gamma B, K gL = K_int e_1 (held left), K gR = K_int e_n.
        const double v = c.K_s * c.v_slider;
        EXPECT_LT((K * vec(b.path.B) - Eigen::VectorXd::Constant(n, v)).cwiseAbs().maxCoeff(), 1e-12 * v);
        const Eigen::VectorXd ma = -c.m * c.gamma * vec(b.path.B);
        EXPECT_LT((K * vec(b.path.a0) - ma).cwiseAbs().maxCoeff(), 1e-12 * ma.cwiseAbs().maxCoeff());
        Eigen::VectorXd eL = Eigen::VectorXd::Zero(n), eR = Eigen::VectorXd::Zero(n);
        if (left) eL[0] = c.K_int;
        if (right) eR[n - 1] = c.K_int;
        EXPECT_LT((K * vec(b.path.gL) - eL).cwiseAbs().maxCoeff(), 1e-12 * c.K_int);
        EXPECT_LT((K * vec(b.path.gR) - eR).cwiseAbs().maxCoeff(), 1e-12 * c.K_int);
      }
}

// A wrong boundary (a held end treated as free) leaves a residual the test above sees.
TEST(RunShape, TheResidualTestSeesAWrongEnd) {
  const sb::Chain c = chain();
  RunShapes shapes(c);
  const RunShape& b = shapes.get(10, true, false);
  const Eigen::MatrixXd K = model_stiffness(c, 10, true, true);
  const Eigen::MatrixXd residual = K * b.Q - b.Q * vec(b.spectrum.lambda).asDiagonal();
  EXPECT_GT(residual.cwiseAbs().maxCoeff(), 1e-3 * c.K_int);
  Eigen::VectorXd y(10);
  const Eigen::VectorXd f = Eigen::VectorXd::Ones(10);
  b.K.solve(f.data(), y.data());
  EXPECT_GT((K * y - f).cwiseAbs().maxCoeff(), 1e-3);
}

}  // namespace

// The general modes (run_shape_general.cpp) of runs whose blocks differ: K Q = W Q diag(lambda) with
// Q^T W Q = I, eigenvalues rising and equal to those of the dense generalised problem; on equal
// blocks they are the closed form's (up to each column's sign). Weights or springs read from the
// wrong rows fail the residual.
TEST(GeneralModes, SolveTheWeightedProblem) {
  const sb::Chain c = chain();
  std::uint64_t x = 12345;
  auto uniform01 = [&x] {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(x >> 11) * 0x1.0p-53;
  };
  for (int n : {1, 2, 3, 7, 40, 120})
    for (bool left : {false, true})
      for (bool right : {false, true}) {
        SCOPED_TRACE("n = " + std::to_string(n) + " left " + std::to_string(left) + " right " + std::to_string(right));
        sb::event_detail::Factors K;
        std::vector<double> w(n), springs(n + 1);
        for (double& s : springs) s = c.K_int * (0.1 + 9.9 * uniform01());  // contrast up to 100
        for (int r = 0; r < n; ++r) {
          w[r] = 0.2 + 4.8 * uniform01();
          const double k_s = c.K_s * (0.5 + uniform01());
          K.diag.push_back(k_s + ((r > 0 || left) ? springs[r] : 0.0) + ((r + 1 < n || right) ? springs[r + 1] : 0.0));
          if (r + 1 < n) K.off.push_back(-springs[r + 1]);
        }
        Eigen::MatrixXd Q;
        std::vector<double> lambda;
        sb::event_detail::general_modes(K, w, Q, lambda);
        const Eigen::MatrixXd Kd = dense(K);
        const Eigen::VectorXd wv = vec(w);
        const double scale = Kd.cwiseAbs().maxCoeff();
        const Eigen::MatrixXd residual = Kd * Q - wv.asDiagonal() * Q * vec(lambda).asDiagonal();
        EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-12 * scale);
        const Eigen::MatrixXd gram = Q.transpose() * wv.asDiagonal() * Q - Eigen::MatrixXd::Identity(n, n);
        EXPECT_LT(gram.cwiseAbs().maxCoeff(), 1e-12);
        const auto reference = sbtest::symmetric_eigen(Kd, Eigen::MatrixXd(wv.asDiagonal())).values;
        for (int k = 0; k < n; ++k) EXPECT_NEAR(lambda[k], reference[k], 1e-12 * scale) << "mode " << k;
      }
  // Equal blocks: the closed form's modes and eigenvalues.
  RunShapes shapes(c);
  for (int n : {1, 4, 33}) {
    const RunShape& b = shapes.get(n, true, false);
    Eigen::MatrixXd Q;
    std::vector<double> lambda;
    sb::event_detail::general_modes(b.K, std::vector<double>(n, 1.0), Q, lambda);
    const double scale = c.K_s + 4.0 * c.K_int;
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(lambda[k], b.spectrum.lambda[k], 1e-12 * scale);
      const double sign = Q.col(k).dot(b.Q.col(k)) < 0 ? -1.0 : 1.0;
      EXPECT_LT((sign * Q.col(k) - b.Q.col(k)).cwiseAbs().maxCoeff(), 1e-10) << "n " << n << " mode " << k;
    }
  }
}
