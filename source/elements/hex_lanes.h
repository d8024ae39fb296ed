#ifndef rubberdyn_source_elements_hex_lanes_h
#define rubberdyn_source_elements_hex_lanes_h

// Kinematics of a block of hexahedra, one element per SIMD lane (private to
// source/elements). Written with GCC's vector extensions: a vector of W
// doubles (VectorOf<W>::type) holds one double per element of W lanes of
// the block, and arithmetic on it is one instruction where the CPU has
// W-wide registers. The hot loop takes a block in chunks of the clone's
// native width (solid_hex_forces.cc: 8 lanes with AVX-512, 4 with AVX2),
// since a vector wider than the registers is lowered by GCC into moves
// through memory (+50 % instructions for 8 lanes on AVX2). The functions
// below take the vector type as a template argument and, where they read
// a block's [...][lanes] arrays, the chunk's first lane. This is explicit
// on purpose: GCC's auto-vectoriser unrolls short lane loops before it
// looks at them and then vectorises some and not others.

#include <rubberdyn/base/simd_math.h>
#include <rubberdyn/elements/solid_hex_elements.h>

#include <algorithm>
#include <cmath>
#include <cstring>

// Every helper below is forced inline: an out-of-line copy of a template
// would be compiled for the baseline instruction set (and shared between
// the versions of the kernel), so the AVX2 version would call an SSE2
// function (seen: reference_jacobians, +45 % instructions).
#define RUBBERDYN_LANES_INLINE inline __attribute__((always_inline))

namespace rubberdyn
{
  namespace elements
  {
    namespace lanes_of
    {
      using internal::HexBlock;
      using internal::n_nodes;
      constexpr unsigned int L = internal::lanes;

      /** W doubles, one per lane of a chunk of W lanes. */
      template <unsigned int W>
      struct VectorOf
      {
        typedef double type __attribute__((vector_size(W * sizeof(double))));
      };

      /** One double per lane of a whole block (set-up and output code). */
      typedef VectorOf<L>::type Lanes;

      /** The number of lanes of the vector type V. */
      template <typename V>
      constexpr unsigned int width = sizeof(V) / sizeof(double);

      // Unaligned loads and stores of width<V> consecutive doubles.
      template <typename V = Lanes>
      RUBBERDYN_LANES_INLINE V
      load(const double *values)
      {
        V v;
        std::memcpy(&v, values, sizeof(v));
        return v;
      }

      template <typename V>
      RUBBERDYN_LANES_INLINE void
      store(const V &v, double *values)
      {
        std::memcpy(values, &v, sizeof(v));
      }

      template <typename V = Lanes>
      RUBBERDYN_LANES_INLINE V
      broadcast(const double x)
      {
        return V{} + x;
      }

      template <typename V>
      RUBBERDYN_LANES_INLINE V
      max(const V &a, const V &b)
      {
        return a > b ? a : b;
      }

      template <typename V>
      RUBBERDYN_LANES_INLINE V
      sqrt(const V &x)
      {
        V y;
        for (unsigned int l = 0; l < width<V>; ++l)
          y[l] = std::sqrt(x[l]);
        return y;
      }

      // Values of a ghosted vector at the nodes of the elements of lanes
      // first_lane, ..., first_lane + width<V> - 1 of the block.
      template <typename V>
      RUBBERDYN_LANES_INLINE void
      gather(const HexBlock &   block,
             const unsigned int first_lane,
             const double *     vector,
             V                  values[n_nodes][3])
      {
        for (unsigned int a = 0; a < n_nodes; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            for (unsigned int l = 0; l < width<V>; ++l)
              values[a][d][l] = vector[block.dofs[a][d][first_lane + l]];
      }

      // Sum factorisation on the reference cube [0,1]^3 with deal.II's
      // lexicographic numbering: node a = i0 + 2 i1 + 4 i2 has N_a =
      // phi_i0(xi_0) phi_i1(xi_1) phi_i2(xi_2), phi_0 = 1 - t, phi_1 = t, and
      // Gauss point q = m0 + 2 m1 + 4 m2 sits at xi_d = gauss[m_d]. So
      // dN_a/dxi_k at q = (+-1) phi_ip(gauss[m_p]) phi_is(gauss[m_s]), with
      // p, s the other two directions: the reference gradient of a field
      // along k is a bilinear interpolation of its 4 edge differences along
      // k, and does not depend on m_k.
      constexpr double gauss_low  = 0.21132486540518711775; // (1 - 1/sqrt3)/2
      constexpr double gauss_high = 0.78867513459481288225; // (1 + 1/sqrt3)/2
      // phi_b(gauss[m]) as [m][b].
      constexpr double phi_at_gauss[2][2] = {{gauss_high, gauss_low},
                                             {gauss_low, gauss_high}};

      inline constexpr unsigned int
      corner(const unsigned int k,
             const unsigned int bit_k,
             const unsigned int bit_p,
             const unsigned int bit_s)
      {
        return (bit_k << k) | (bit_p << ((k + 1) % 3)) |
               (bit_s << ((k + 2) % 3));
      }

      // Reference gradients H[r][k] = sum_a u_a[r] dN_a/dxi_k of the nodal
      // field u at the 8 Gauss points and at the centre.
      template <typename V>
      RUBBERDYN_LANES_INLINE void
      reference_gradients(const V u[n_nodes][3],
                          V       H[internal::n_q][3][3],
                          V       H_centre[3][3])
      {
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int k = 0; k < 3; ++k)
            {
              V D[2][2];
              for (unsigned int bp = 0; bp < 2; ++bp)
                for (unsigned int bs = 0; bs < 2; ++bs)
                  D[bp][bs] =
                    u[corner(k, 1, bp, bs)][r] - u[corner(k, 0, bp, bs)][r];
              H_centre[r][k] = 0.25 * (D[0][0] + D[0][1] + D[1][0] + D[1][1]);
              V T[2][2];
              for (unsigned int bp = 0; bp < 2; ++bp)
                for (unsigned int ms = 0; ms < 2; ++ms)
                  T[bp][ms] = phi_at_gauss[ms][0] * D[bp][0] +
                              phi_at_gauss[ms][1] * D[bp][1];
              for (unsigned int mp = 0; mp < 2; ++mp)
                for (unsigned int ms = 0; ms < 2; ++ms)
                  {
                    const V value = phi_at_gauss[mp][0] * T[0][ms] +
                                        phi_at_gauss[mp][1] * T[1][ms];
                    H[corner(k, 0, mp, ms)][r][k] = value;
                    H[corner(k, 1, mp, ms)][r][k] = value;
                  }
            }
      }

      // The transpose: f_a[r] += sum_q sum_k B_q[r][k] dN_a/dxi_k(q).
      template <typename V>
      RUBBERDYN_LANES_INLINE void
      add_reference_divergence(const V B[internal::n_q][3][3],
                               V       f[n_nodes][3])
      {
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int k = 0; k < 3; ++k)
            {
              V P[2][2];
              for (unsigned int mp = 0; mp < 2; ++mp)
                for (unsigned int ms = 0; ms < 2; ++ms)
                  P[mp][ms] = B[corner(k, 0, mp, ms)][r][k] +
                              B[corner(k, 1, mp, ms)][r][k];
              V T[2][2];
              for (unsigned int mp = 0; mp < 2; ++mp)
                for (unsigned int bs = 0; bs < 2; ++bs)
                  T[mp][bs] = phi_at_gauss[0][bs] * P[mp][0] +
                              phi_at_gauss[1][bs] * P[mp][1];
              for (unsigned int bp = 0; bp < 2; ++bp)
                for (unsigned int bs = 0; bs < 2; ++bs)
                  {
                    const V E = phi_at_gauss[0][bp] * T[0][bs] +
                                    phi_at_gauss[1][bp] * T[1][bs];
                    f[corner(k, 1, bp, bs)][r] += E;
                    f[corner(k, 0, bp, bs)][r] -= E;
                  }
            }
      }

      // F = I + H dxi/dX, dxi/dX of the lanes from first_lane on.
      template <typename V>
      RUBBERDYN_LANES_INLINE void
      deformation_gradient(const V            H[3][3],
                           const double       inverse_jacobian[3][3][L],
                           V                  F[3][3],
                           const unsigned int first_lane = 0)
      {
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int c = 0; c < 3; ++c)
            F[r][c] =
              (r == c ? 1. : 0.) +
              H[r][0] * load<V>(inverse_jacobian[0][c] + first_lane) +
              H[r][1] * load<V>(inverse_jacobian[1][c] + first_lane) +
              H[r][2] * load<V>(inverse_jacobian[2][c] + first_lane);
      }

      // F = I + H dxi/dX with dxi/dX [k][c] per lane.
      template <typename V>
      RUBBERDYN_LANES_INLINE void
      deformation_gradient(const V H[3][3],
                           const V inverse_jacobian[3][3],
                           V       F[3][3])
      {
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int c = 0; c < 3; ++c)
            F[r][c] = (r == c ? 1. : 0.) + H[r][0] * inverse_jacobian[0][c] +
                      H[r][1] * inverse_jacobian[1][c] +
                      H[r][2] * inverse_jacobian[2][c];
      }

      // J = det F and G = F^{-T} = cof(F) / J.
      template <typename V>
      RUBBERDYN_LANES_INLINE void
      determinant_and_inverse_transpose(const V F[3][3], V &J, V G[3][3])
      {
        const V c00 = F[1][1] * F[2][2] - F[1][2] * F[2][1];
        const V c01 = F[1][2] * F[2][0] - F[1][0] * F[2][2];
        const V c02 = F[1][0] * F[2][1] - F[1][1] * F[2][0];
        J           = F[0][0] * c00 + F[0][1] * c01 + F[0][2] * c02;
        const V s   = 1. / J;
        G[0][0]         = s * c00;
        G[0][1]         = s * c01;
        G[0][2]         = s * c02;
        G[1][0]         = s * (F[0][2] * F[2][1] - F[0][1] * F[2][2]);
        G[1][1]         = s * (F[0][0] * F[2][2] - F[0][2] * F[2][0]);
        G[1][2]         = s * (F[0][1] * F[2][0] - F[0][0] * F[2][1]);
        G[2][0]         = s * (F[0][1] * F[1][2] - F[0][2] * F[1][1]);
        G[2][1]         = s * (F[0][2] * F[1][0] - F[0][0] * F[1][2]);
        G[2][2]         = s * (F[0][0] * F[1][1] - F[0][1] * F[1][0]);
      }

      // The Jacobians of the map from the reference cube of the lanes
      // first_lane, ... of a block, from their nodal coordinates X (the
      // trilinear map, deal.II's MappingQ1 with which
      // SolidHexElements::initialize() fills HexBlock::inverse_jacobian and
      // JxW; the same to round-off): dxi/dX [k][c] and det(dX/dxi) at the
      // Gauss points, and dxi/dX at the centre. Recomputing them costs about
      // 220 instructions per element in the AVX2 version (callgrind; 9
      // inversions of 3x3 matrices); reading them would stream 89 stored
      // doubles per element from memory, which bounded the kernel's speed
      // once the mesh outgrew the caches (benchmarks/README.md).
      template <typename V>
      RUBBERDYN_LANES_INLINE void
      reference_jacobians(const HexBlock &   block,
                          const unsigned int first_lane,
                          V                  inverse_jacobian[internal::n_q][3][3],
                          V                  determinant[internal::n_q],
                          V                  inverse_jacobian_centre[3][3])
      {
        V X[n_nodes][3];
        for (unsigned int a = 0; a < n_nodes; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            X[a][d] = load<V>(block.X[a][d] + first_lane);
        V dX[internal::n_q][3][3], dX_centre[3][3];
        reference_gradients(X, dX, dX_centre);
        V G[3][3];
        for (unsigned int q = 0; q < internal::n_q; ++q)
          {
            determinant_and_inverse_transpose(dX[q], determinant[q], G);
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int c = 0; c < 3; ++c)
                inverse_jacobian[q][k][c] = G[c][k];
          }
        V det_centre;
        determinant_and_inverse_transpose(dX_centre, det_centre, G);
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int c = 0; c < 3; ++c)
            inverse_jacobian_centre[k][c] = G[c][k];
      }

      // Length l of the element step Delta t = l / c (doc/theory.md,
      // section 8.3): the bound of Flanagan and Belytschko (IJNME 17
      // (1981) 679-706) on the largest frequency of a hexahedron with
      // lumped mass, generalised to nodal masses m_a = mu_a M (M the
      // element's mass),
      //   omega_max^2 <= c^2 sum_a |g0_a|^2 / mu_a = (2 c / l)^2,
      //   l = 2 / sqrt(sum_a |g0_a|^2 / mu_a),
      // with g0_a the gradient of N_a at the centre in the configuration
      // the wave speed c is measured in, and inverse_mass_fraction[a] =
      // 1 / mu_a. For a parallelepiped (mu_a = 1/8) l = V / sqrt(A_1^2 +
      // A_2^2 + A_3^2) with A_i the areas of its three face pairs: h / sqrt3
      // for a cube of side h, whose breathing mode attains the bound.
      template <typename V>
      RUBBERDYN_LANES_INLINE V
      characteristic_length(const V            g0[n_nodes][3],
                            const double       inverse_mass_fraction[n_nodes][L],
                            const unsigned int first_lane = 0)
      {
        V sum = {};
        for (unsigned int a = 0; a < n_nodes; ++a)
          sum += load<V>(inverse_mass_fraction[a] + first_lane) *
                 (g0[a][0] * g0[a][0] + g0[a][1] * g0[a][1] +
                  g0[a][2] * g0[a][2]);
        return 2. / sqrt(sum);
      }

      // x^(-1/3) per lane, as simd_math::inverse_cube_root.
      template <typename V>
      RUBBERDYN_LANES_INLINE V
      inverse_cube_root(const V &x)
      {
        typedef float Floats
          __attribute__((vector_size(width<V> * sizeof(float))));
        typedef std::int32_t Ints
          __attribute__((vector_size(width<V> * sizeof(std::int32_t))));
        const Floats x_float = __builtin_convertvector(x, Floats);
        Ints         bits;
        std::memcpy(&bits, &x_float, sizeof(bits));
        bits = simd_math::inverse_cube_root_magic - bits / 3;
        Floats y_float;
        std::memcpy(&y_float, &bits, sizeof(bits));
        V y = __builtin_convertvector(y_float, V);
        for (unsigned int k = 0; k < simd_math::inverse_cube_root_newton_steps;
             ++k)
          y = y * (4. - x * (y * y * y)) * (1. / 3.);
        return y;
      }
    } // namespace lanes_of



    /**
     * Whether @p plane cuts the element of lane @p l of @p block: nodes
     * strictly on both sides of it, beyond 1e-9 of the element's size (a
     * plane on the element's faces does not cut it). If it does, @p
     * far_side tells for each node whether it lies on the normal's side.
     * Pretension sections and cross sections cut alike
     * (SolidHexElements::cut_sections(), section_resultants()).
     */
    inline bool
    plane_cuts_element(const internal::HexBlock &block,
                       const unsigned int        l,
                       const SectionPlane       &plane,
                       bool                      far_side[internal::n_nodes])
    {
      constexpr unsigned int n_nodes = internal::n_nodes;
      double distance[n_nodes], lo = 0., hi = 0., size = 0.;
      for (unsigned int a = 0; a < n_nodes; ++a)
        {
          distance[a] = 0.;
          for (unsigned int d = 0; d < 3; ++d)
            {
              distance[a] +=
                (block.X[a][d][l] - plane.point[d]) * plane.normal[d];
              size = std::max(size,
                              std::abs(block.X[a][d][l] - block.X[0][d][l]));
            }
          lo = std::min(lo, distance[a]);
          hi = std::max(hi, distance[a]);
        }
      const double tolerance = 1e-9 * size;
      if (!(lo < -tolerance && hi > tolerance))
        return false;
      for (unsigned int a = 0; a < n_nodes; ++a)
        far_side[a] = distance[a] > tolerance;
      return true;
    }
  }   // namespace elements
} // namespace rubberdyn

#endif
