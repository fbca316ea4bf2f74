/*! \file Types.hpp
 *  \brief Execution/memory spaces, View aliases and small fixed-size vector algebra for the kernels.
 *
 *  Everything in kernels/ includes Kokkos core only (never Tpetra), so the same headers build for a GPU
 *  backend. Fields are LayoutLeft 2-D Views (entity x component): that is the layout of a Tpetra
 *  MultiVector's device view, so the src/ layer hands MultiVector storage to the kernels without copies,
 *  and it is structure-of-arrays, which vectorises on CPUs and coalesces on GPUs.
 */
#pragma once

#include <Kokkos_Core.hpp>

namespace unilag
{

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;
using LO = int;  //!< local ordinal (cells, nodes, corners on one rank)

template <class T>
using View = Kokkos::View<T, MemSpace>;
//! entity x component field, the storage of a Tpetra::MultiVector
using Field = Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace>;
using ConstField = Kokkos::View<const double**, Kokkos::LayoutLeft, MemSpace>;
/*! entity x component field that kernels gather whole rows of (a cell's corner vectors, read by every node of the
 *  cell): one row per cache line or two on the host (LayoutRight), columns on a GPU (its coalescing layout). */
using RowField = Kokkos::View<double**, ExecSpace::array_layout, MemSpace>;

template <class Policy = ExecSpace>
inline Kokkos::RangePolicy<Policy> range(std::size_t n)
{
    return Kokkos::RangePolicy<Policy>(0, n);
}

/*! nvcc cannot capture a variable into an extended lambda where the lambda first names it inside `if constexpr`;
 *  such a lambda names those variables at its top with `captureBeforeConstexpr(a, b)` (a no-op). */
template <class... T>
KOKKOS_INLINE_FUNCTION void captureBeforeConstexpr(const T&...)
{
}

//! Small vector in D dimensions (D = 2 or 3), usable inside kernels.
template <int D>
struct Vec
{
    double v[D];
    KOKKOS_INLINE_FUNCTION double& operator[](int i) { return v[i]; }
    KOKKOS_INLINE_FUNCTION double operator[](int i) const { return v[i]; }
    KOKKOS_INLINE_FUNCTION static Vec zero()
    {
        Vec r;
        for (int i = 0; i < D; ++i)
            r.v[i] = 0.0;
        return r;
    }
};

template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> operator+(const Vec<D>& a, const Vec<D>& b)
{
    Vec<D> r;
    for (int i = 0; i < D; ++i)
        r[i] = a[i] + b[i];
    return r;
}
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> operator-(const Vec<D>& a, const Vec<D>& b)
{
    Vec<D> r;
    for (int i = 0; i < D; ++i)
        r[i] = a[i] - b[i];
    return r;
}
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> operator*(double s, const Vec<D>& a)
{
    Vec<D> r;
    for (int i = 0; i < D; ++i)
        r[i] = s * a[i];
    return r;
}
template <int D>
KOKKOS_INLINE_FUNCTION double dot(const Vec<D>& a, const Vec<D>& b)
{
    double s = 0.0;
    for (int i = 0; i < D; ++i)
        s += a[i] * b[i];
    return s;
}
template <int D>
KOKKOS_INLINE_FUNCTION double norm(const Vec<D>& a)
{
    return Kokkos::Experimental::sqrt(dot(a, a));
}

/*! fmin / fmax as comparisons: on the host std::fmin is a call into libm (for its NaN rules), 7% of an order-2 step
 *  when the limiter's bounds used it. Like fmin, a NaN b is passed over (a stays); a NaN a stays NaN (fmin would take
 *  b), which only a state already lost can give. */
KOKKOS_INLINE_FUNCTION double lesser(double a, double b) { return b < a ? b : a; }
KOKKOS_INLINE_FUNCTION double greater(double a, double b) { return b > a ? b : a; }

/*! \brief Orthonormal basis Q[0, returned) of the span of the n vectors u (Gram-Schmidt, in order): a vector whose
 *  part orthogonal to the earlier ones is below 1e-8 of its length adds nothing (parallel walls count once). Exact
 *  copies of orthogonal unit inputs for axis-aligned planes, so results there do not change by round-off. */
template <int D>
KOKKOS_INLINE_FUNCTION int orthonormalBasis(const Vec<D>* u, int n, Vec<D> (&Q)[D])
{
    int nq = 0;
    for (int s = 0; s < n && nq < D; ++s)
    {
        Vec<D> w = u[s];
        const double len0 = norm(w);
        for (int a = 0; a < nq; ++a)
            w = w - dot(w, Q[a]) * Q[a];
        const double len = norm(w);
        if (len > 1e-8 * len0)
            Q[nq++] = (1.0 / len) * w;
    }
    return nq;
}

/*! \brief Adds a slip-wall face's outward normal n to the wall planes through a node (sums of their faces' normals):
 *  to the plane it is closest to if within ~45 degrees of it (cosine above 0.7: a curved or faceted wall), else as a
 *  new plane while fewer than N are held. Signed: walls meeting at a sharp wedge, whose outward normals point more
 *  than 135 degrees apart, are two planes (a test on |cosine| merged any wedge under 45.6 degrees into one plane
 *  through its bisector). One rule for the nodal solver's constraints and the reconstruction's mirror images. */
template <int D, int N>
KOKKOS_INLINE_FUNCTION void addWallNormal(const Vec<D>& n, Vec<D> (&plane)[N], int& nPlanes)
{
    const double len = norm(n);
    int best = -1;
    double bestCos = 0.7;
    for (int p = 0; p < nPlanes; ++p)
    {
        const double cosine = dot(n, plane[p]) / (len * norm(plane[p]));
        if (cosine > bestCos)
        {
            bestCos = cosine;
            best = p;
        }
    }
    if (best < 0 && nPlanes < N)
    {
        best = nPlanes++;
        plane[best] = Vec<D>::zero();
    }
    if (best >= 0)
        plane[best] = plane[best] + n;
}

//! Symmetric D x D matrix stored full (D <= 3 keeps this in registers).
template <int D>
struct Mat
{
    double a[D][D];
    KOKKOS_INLINE_FUNCTION static Mat zero()
    {
        Mat m;
        for (int i = 0; i < D; ++i)
            for (int j = 0; j < D; ++j)
                m.a[i][j] = 0.0;
        return m;
    }
    KOKKOS_INLINE_FUNCTION Vec<D> operator*(const Vec<D>& x) const
    {
        Vec<D> r;
        for (int i = 0; i < D; ++i)
        {
            double s = 0.0;
            for (int j = 0; j < D; ++j)
                s += a[i][j] * x[j];
            r[i] = s;
        }
        return r;
    }
    //! this += s * (u outer u)
    KOKKOS_INLINE_FUNCTION void addOuter(double s, const Vec<D>& u)
    {
        for (int i = 0; i < D; ++i)
            for (int j = 0; j < D; ++j)
                a[i][j] += s * u[i] * u[j];
    }
};

//! det M (D = 2, 3), expanded along the first row.
template <int D>
KOKKOS_INLINE_FUNCTION double determinant(const Mat<D>& M)
{
    const auto& a = M.a;
    if constexpr (D == 2)
        return a[0][0] * a[1][1] - a[0][1] * a[1][0];
    else
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

//! Solve M x = b for small SPD M by Cramer's rule (D = 1, 2, 3).
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> solve(const Mat<D>& M, const Vec<D>& b)
{
    Vec<D> x;
    if constexpr (D == 1)
    {
        x[0] = b[0] / M.a[0][0];
    }
    else if constexpr (D == 2)
    {
        const double det = M.a[0][0] * M.a[1][1] - M.a[0][1] * M.a[1][0];
        x[0] = (M.a[1][1] * b[0] - M.a[0][1] * b[1]) / det;
        x[1] = (M.a[0][0] * b[1] - M.a[1][0] * b[0]) / det;
    }
    else
    {
        const auto& a = M.a;
        const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
        const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
        const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
        const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
        const double inv = 1.0 / det;
        x[0] = inv * (c00 * b[0] + (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * b[1] +
                      (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * b[2]);
        x[1] = inv * (c01 * b[0] + (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * b[1] +
                      (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * b[2]);
        x[2] = inv * (c02 * b[0] + (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * b[1] +
                      (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * b[2]);
    }
    return x;
}

} // namespace unilag
