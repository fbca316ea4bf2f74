#include "tube/Lapack.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

extern "C"
{
    void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
    void dpotrs_(const char* uplo, const int* n, const int* nrhs, const double* a, const int* lda, double* b,
                 const int* ldb, int* info);
    void dsygv_(const int* itype, const char* jobz, const char* uplo, const int* n, double* a, const int* lda,
                double* b, const int* ldb, double* w, double* work, const int* lwork, int* info);
    void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* wr, double* wi,
                double* vl, const int* ldvl, double* vr, const int* ldvr, double* work, const int* lwork, int* info);
    void dggev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* b,
                const int* ldb, double* alphar, double* alphai, double* beta, double* vl, const int* ldvl, double* vr,
                const int* ldvr, double* work, const int* lwork, int* info);
}

namespace unilag::tube::lapack
{

Matrix solveSpd(const Matrix& m, const Matrix& b)
{
    Matrix factor = m, x = b;
    const int n = m.n;
    int info = 0;
    dpotrf_("L", &n, factor.a.data(), &n, &info);
    if (info != 0)
        throw std::runtime_error("mass matrix not positive definite (dpotrf info " + std::to_string(info) + ")");
    dpotrs_("L", &n, &n, factor.a.data(), &n, x.a.data(), &n, &info);
    return x;
}

void symmetricEigenpairs(const Matrix& a, const Matrix& b, int count, std::vector<double>& values,
                         std::vector<double>& vectors)
{
    Matrix wa = a, wb = b;
    const int n = a.n, itype = 1;
    std::vector<double> w(n);
    double query = 0.0;
    int lwork = -1, info = 0;
    dsygv_(&itype, "V", "L", &n, wa.a.data(), &n, wb.a.data(), &n, w.data(), &query, &lwork, &info);
    lwork = int(query);
    std::vector<double> scratch(std::max(1, lwork));
    dsygv_(&itype, "V", "L", &n, wa.a.data(), &n, wb.a.data(), &n, w.data(), scratch.data(), &lwork, &info);
    if (info != 0)
        throw std::runtime_error("dsygv failed (info " + std::to_string(info) + ")");
    values.assign(w.begin(), w.begin() + count);
    vectors.assign(wa.a.begin(), wa.a.begin() + std::size_t(n) * count);
}

std::vector<std::complex<double>> eigenvalues(const Matrix& a)
{
    Matrix work = a;
    const int n = a.n, one = 1;
    std::vector<double> wr(n), wi(n);
    double dummy = 0.0, query = 0.0;
    int lwork = -1, info = 0;
    dgeev_("N", "N", &n, work.a.data(), &n, wr.data(), wi.data(), &dummy, &one, &dummy, &one, &query, &lwork, &info);
    lwork = int(query);
    std::vector<double> scratch(std::max(1, lwork));
    dgeev_("N", "N", &n, work.a.data(), &n, wr.data(), wi.data(), &dummy, &one, &dummy, &one, scratch.data(), &lwork,
           &info);
    if (info != 0)
        throw std::runtime_error("dgeev did not converge (info " + std::to_string(info) + ")");
    std::vector<std::complex<double>> lambda(n);
    for (int i = 0; i < n; ++i)
        lambda[i] = {wr[i], wi[i]};
    return lambda;
}

std::vector<std::complex<double>> generalizedEigenvalues(const Matrix& a, const Matrix& b)
{
    Matrix wa = a, wb = b;
    const int n = a.n, one = 1;
    std::vector<double> ar(n), ai(n), be(n);
    double dummy = 0.0, query = 0.0;
    int lwork = -1, info = 0;
    dggev_("N", "N", &n, wa.a.data(), &n, wb.a.data(), &n, ar.data(), ai.data(), be.data(), &dummy, &one, &dummy, &one,
           &query, &lwork, &info);
    lwork = int(query);
    std::vector<double> scratch(std::max(1, lwork));
    dggev_("N", "N", &n, wa.a.data(), &n, wb.a.data(), &n, ar.data(), ai.data(), be.data(), &dummy, &one, &dummy, &one,
           scratch.data(), &lwork, &info);
    if (info != 0)
        throw std::runtime_error("dggev did not converge (info " + std::to_string(info) + ")");
    // beta ~ 0 relative to alpha is an infinite eigenvalue (a direction B does not see)
    std::vector<std::complex<double>> mu;
    for (int i = 0; i < n; ++i)
        if (std::abs(be[i]) > 1e-13 * std::hypot(ar[i], ai[i]))
            mu.emplace_back(ar[i] / be[i], ai[i] / be[i]);
    return mu;
}

} // namespace unilag::tube::lapack
