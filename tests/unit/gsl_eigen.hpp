#pragma once
// The tests' reference for small dense symmetric eigenproblems, K x = lambda M x: GSL's solver,
// independent of the Eigen one the library uses. GSL comes compiled; Eigen's eigensolvers,
// instantiated in a test file, took 11 to 16 s of its compile time (g++ -O3), more than the rest
// of the file.
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace sbtest {

struct SymmetricEigen {
  std::vector<double> values;  // ascending
  Eigen::MatrixXd vectors;     // column k belongs to values[k], scaled to x^T M x = 1
};

inline SymmetricEigen symmetric_eigen(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  const auto n = static_cast<std::size_t>(K.rows());
  gsl_matrix* A = gsl_matrix_alloc(n, n);
  gsl_matrix* B = gsl_matrix_alloc(n, n);
  gsl_matrix* V = gsl_matrix_alloc(n, n);
  gsl_vector* lambda = gsl_vector_alloc(n);
  gsl_eigen_gensymmv_workspace* work = gsl_eigen_gensymmv_alloc(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      gsl_matrix_set(A, i, j, K(Eigen::Index(i), Eigen::Index(j)));
      gsl_matrix_set(B, i, j, M(Eigen::Index(i), Eigen::Index(j)));
    }
  gsl_eigen_gensymmv(A, B, lambda, V, work);
  gsl_eigen_gensymmv_sort(lambda, V, GSL_EIGEN_SORT_VAL_ASC);
  SymmetricEigen out{std::vector<double>(n), Eigen::MatrixXd(Eigen::Index(n), Eigen::Index(n))};
  for (std::size_t k = 0; k < n; ++k) {
    out.values[k] = gsl_vector_get(lambda, k);
    for (std::size_t i = 0; i < n; ++i)
      out.vectors(Eigen::Index(i), Eigen::Index(k)) = gsl_matrix_get(V, i, k);
    const Eigen::VectorXd x = out.vectors.col(Eigen::Index(k));
    out.vectors.col(Eigen::Index(k)) /= std::sqrt(x.dot(M * x));
  }
  gsl_eigen_gensymmv_free(work);
  gsl_vector_free(lambda);
  gsl_matrix_free(V);
  gsl_matrix_free(B);
  gsl_matrix_free(A);
  return out;
}

}  // namespace sbtest
