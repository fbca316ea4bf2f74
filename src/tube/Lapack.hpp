/*! \file Lapack.hpp
 *  \brief The three dense LAPACK calls the tube's linear stability needs, on column-major matrices.
 *
 *  Declared through extern "C" (Debian's liblapack) so that the tube module needs no Trilinos header: the
 *  matrices here are small (tens to a few hundred rows) and dense.
 */
#pragma once

#include <complex>
#include <vector>

namespace unilag::tube::lapack
{

//! A dense column-major n x n matrix.
struct Matrix
{
    int n = 0;
    std::vector<double> a; //!< a[i + j n] = A(i, j)

    explicit Matrix(int size = 0) : n(size), a(std::size_t(size) * size, 0.0) {}
    double& operator()(int i, int j) { return a[i + std::size_t(j) * n]; }
    double operator()(int i, int j) const { return a[i + std::size_t(j) * n]; }
};

//! M^{-1} B for a symmetric positive definite M (Cholesky). Throws std::runtime_error if M is not SPD.
Matrix solveSpd(const Matrix& m, const Matrix& b);

/*! The `count` lowest eigenpairs of the symmetric-definite problem A x = mu B x (dsygv): values ascending,
 *  vectors as the columns of an n x count column-major array, B-orthonormal. */
void symmetricEigenpairs(const Matrix& a, const Matrix& b, int count, std::vector<double>& values,
                         std::vector<double>& vectors);

//! The eigenvalues of a general real matrix (dgeev, no vectors).
std::vector<std::complex<double>> eigenvalues(const Matrix& a);

//! The finite eigenvalues mu of A x = mu B x (dggev); pairs with |beta| tiny (infinite mu) are left out.
std::vector<std::complex<double>> generalizedEigenvalues(const Matrix& a, const Matrix& b);

} // namespace unilag::tube::lapack
