!> Axisymmetric (r, z) SPH: the pointwise formulas (cases/axisymmetric/README.md gives the
!> equations, the derivation and the measurements). Particles live in the meridian half-plane,
!> x = r >= 0, the symmetry axis is the line x = 0; a particle stands for a ring and carries
!> its true 3D mass m = rho 2 pi r A (A its area in the meridian plane). The axis is closed by
!> mirror images (loops/particle_images.f90): an image carries its source's mass, density and
!> pressure at (-x, z) with the velocity (-u, w).
!>   density      rho_a = sum_b mu_b W_ab / g_a over the rings and their images, mu = m / 2pi,
!>                g = the kernel's smoothed radius (axis_weight_tables): the interpolant of
!>                |x| over the mirrored half-plane, so that a uniform field gives rho exactly,
!>                on the axis too; g(0) ~ 0.4 h > 0, g = |x| beyond 2h. The density is not
!>                summed (SPHysics' continuity is kept); its time derivative is the continuity
!>   continuity   drho_a/dt = (1/g_a) sum_b mu_b (v_a - v_b) . grad_a W_ab - rho_a (g'_a/g_a) u_a
!>                (-rho (div v + u/r) far from the axis; for u = A r exact at every x)
!>   momentum     the Euler-Lagrange force of the energy sum_a m_a e(rho_a) with that density:
!>                du_a/dt = -sum_b mu_b (P_a/g_a + P_b/g_b) grad_a W_ab + (p_a/rho_a)(g'_a/g_a) e_r,
!>                P = p/rho^2. The pair conserves sum_a m_a (v_a^2/2 + e(rho_a)) exactly,
!>                mirror images included, and z-momentum; it is the form of Garcia-Senz,
!>                Relano, Cabezon & Bravo (2012, MNRAS 422, 3449) with g in place of r.
!>                Its one inconsistency: a uniform pressure pushes particles within 2h of the
!>                axis with -P rho (|x|/g)~' (the smoothed slope of |x|/g), which the liquid
!>                there balances with a pressure 13% above the rest at R/dx = 10 (README).
!>   rings pair   (domain.axis_pair = "rings") in place of the three lines above:
!>                rho_a = sum_b m_b Wr_ab, Wr the 3D kernel averaged over the azimuth of ring
!>                b (ring_kernel_tables): the 3D SPH density of the rings, without images or
!>                axis weight, its continuity and Euler-Lagrange force (loops/
!>                axisymmetric_loops.f90, ring_pairs). No uniform-pressure error in the
!>                continuum; the lattice's (the midpoint rule's at the axis) is corrected to
!>                leading order by 11/12 of the first column's masses (README).
!>   viscosity    du_r/dt += nu ((1/r) du_r/dr - u_r / r^2),  du_z/dt += nu (1/r) du_z/dr
!>   CSF          kappa = div_2D nhat + nhat_r / r  (both principal curvatures)
!> The viscous hoop terms and the azimuthal curvature take 1/r as 1/max(r, R_MIN_H h)
!> (axis_radius), and the in-plane operators (viscosity, XSPH, colour, normal) the planar
!> mass m / (2 pi max(r, R_MIN_H h)) = rho A: a lattice particle (r >= dx/2 = 0.38 h at
!> h = 1.3 dx) never feels the bound, it only bounds the terms of a particle that reaches the
!> axis. The azimuthal curvature nhat_r / r, whose numerator is a small difference near the
!> axis, is blended within r < h towards the in-plane one: a smooth axisymmetric surface
!> meets the axis at an umbilic, where both principal curvatures are equal.
module axisymmetric
  use sphjet_kinds, only: rp, pi
  implicit none
  private
  public :: axis_radius, planar_mass, mass_per_radian, viscous_hoop, azimuthal_curvature, &
            R_MIN_H, axis_weight_tables, axis_weights, AXIS_TABLE_N, axis_detection_factor, &
            ring_kernel_tables, ring_kernel_derivs, RING_NU, RING_NV, &
            ring_too_heavy

  !> Smallest radius used in 1/r, in units of h.
  real(rp), parameter :: R_MIN_H = 0.25_rp
  !> Smoothed-radius tables (axis_weight_tables): points, extent [h], grid of the sums [h].
  integer, parameter :: AXIS_TABLE_N = 201
  real(rp), parameter :: AXIS_TABLE_X = 2.0_rp, AXIS_GRID_D = 0.001_rp
  !> Ring-kernel tables (ring_kernel_tables): points in u = s^2/(2h)^2 and v = p/(p + h^2).
  integer, parameter :: RING_NU = 257, RING_NV = 257

contains

  !> domain.split_axis_rings: whether a ring of mass m at x is to be split in two. A fluid ring
  !> of mass m at radius r has the meridian area m / (2 pi r rho): a ring that reaches the axis
  !> from further out stands for more area than one kernel can hold (at r -> 0 its mass is a
  !> point of the 3D density, m W(0): five lattice rings' worth for the ring built at 2.5 dx).
  !> It is too heavy when m > max(2 mu r, m_axis): more than twice the lattice ring's mass at its
  !> radius (mu = 2 pi rho0 dx dz, the lattice ring's mass per unit radius), and never below
  !> m_axis = 2 pi rho0 dx^2 dz, twice the first column's (r = dx/2) ring, so that the rings at
  !> the axis end at most that heavy.
  pure elemental logical function ring_too_heavy(m, x, mu, m_axis)
    real(rp), intent(in) :: m, x, mu, m_axis
    ring_too_heavy = mu > 0.0_rp .and. m > max(2.0_rp * mu * abs(x), m_axis)
  end function ring_too_heavy

  !> The radius used in 1/r: max(|x|, R_MIN_H h) [m].
  pure elemental function axis_radius(x, h) result(r)
    real(rp), intent(in) :: x, h
    real(rp) :: r
    r = max(abs(x), R_MIN_H * h)
  end function axis_radius

  !> The planar mass of a ring particle of mass m at x: m / (2 pi r) = rho A [kg/m].
  pure elemental function planar_mass(m, x, h) result(mp)
    real(rp), intent(in) :: m, x, h
    real(rp) :: mp
    mp = m / (2.0_rp * pi * axis_radius(x, h))
  end function planar_mass

  !> The ring mass per radian m / (2 pi) of a particle at x from its planar mass mp (the
  !> inverse of planar_mass) [kg].
  pure elemental function mass_per_radian(mp, x, h) result(mu)
    real(rp), intent(in) :: mp, x, h
    real(rp) :: mu
    mu = mp * axis_radius(x, h)
  end function mass_per_radian

  !> The hoop terms of the viscous acceleration, nu ((1/r) du_r/dr - u_r / r^2) (radial) and
  !> nu (1/r) du_z/dr (axial); dudr, dwdr the radial derivatives of u_r and u_z [1/s].
  pure elemental subroutine viscous_hoop(nu, u, dudr, dwdr, x, h, ax, az)
    real(rp), intent(in) :: nu, u, dudr, dwdr, x, h
    real(rp), intent(out) :: ax, az
    real(rp) :: r
    r = axis_radius(x, h)
    ax = nu * (dudr / r - u / (r * r))
    az = nu * dwdr / r
  end subroutine viscous_hoop

  !> The azimuthal curvature nhat_r / r of a particle at x with unit normal component nhx (into
  !> the liquid) and in-plane curvature kin (the same sign convention, -1/R for a sphere): for
  !> r >= h nhat_r / r; for r < h the blend (r/h) nhat_r / r + (1 - r/h) kin, which tends to
  !> the in-plane curvature at the axis (umbilic) and never divides by a small r.
  pure elemental function azimuthal_curvature(nhx, x, kin, h) result(kaz)
    real(rp), intent(in) :: nhx, x, kin, h
    real(rp) :: kaz
    real(rp) :: r, nr
    r = abs(x)
    nr = sign(1.0_rp, x) * nhx
    if (r >= h) then
      kaz = nr / r
    else
      kaz = nr / h + (1.0_rp - r / h) * kin
    end if
  end function azimuthal_curvature

  !> The factor min(1, |x| / (2h)) on the radial component of the colour gradient with which
  !> the CSF decides where the free surface is (its filter and surface weight; the gradient is
  !> that of the mode's own colour (1/g_a) sum_b (m_b / (2 pi rho_b)) W_ab, see
  !> surface_tension_loops.f90). On the lattice that colour is 6% high on the row next to the
  !> axis (the lattice sum of |x| W is not the integral g there), which gives interior rings a
  !> radial gradient |n| h = 0.065, above the surface weight's ramp (0.025-0.075; the outer
  !> rows have 0.12). The radial normal is odd in r and vanishes on the axis, so a surface that
  !> meets the axis (a pole) has its normal along z and keeps its weight.
  pure elemental function axis_detection_factor(x, h) result(f)
    real(rp), intent(in) :: x, h
    real(rp) :: f
    f = min(1.0_rp, abs(x) / (2.0_rp * h))
  end function axis_detection_factor

  !> The kernel's smoothed radius g(x) = int |x'| P(x - x') dx' (P(y) = int W(y, s) ds, the
  !> kernel's profile across a line): the meridian-plane SPH interpolant of |x| over a set
  !> closed by its mirror image, even, smooth, g(0) > 0 and g(x) = |x| for |x| >= 2h. Tables
  !> over x = 0 ... AXIS_TABLE_X h (h = 1, AXIS_TABLE_N points) of gi = 1/g and
  !> hoop = g'/g; midpoint sums on a grid of AXIS_GRID_D h (g(2h) = 2 to 1e-6).
  pure subroutine axis_weight_tables(kind, gi, hoop)
    use sphjet_kinds, only: ip
    use sphjet_kernels, only: kernel_t, kernel_setup, kernel_profile
    integer(ip), intent(in) :: kind
    real(rp), intent(out) :: gi(AXIS_TABLE_N), hoop(AXIS_TABLE_N)
    real(rp), parameter :: D = AXIS_GRID_D
    integer, parameter :: NP = nint(2.0_rp / AXIS_GRID_D), NQ = 400
    type(kernel_t) :: kern
    real(rp) :: prof(-NP:NP), x, g, gp
    integer :: i, j, k
    kern = kernel_setup(kind, 1.0_rp)
    do i = -NP, NP
      prof(i) = kernel_profile(kern, i * D, NQ)
    end do
    prof = prof / (sum(prof) * D)   ! unit integral on the grid
    do k = 1, AXIS_TABLE_N
      x = (k - 1) * AXIS_TABLE_X / (AXIS_TABLE_N - 1)
      g = 0.0_rp
      gp = 0.0_rp
      do j = -NP, NP   ! g = sum |x - y| P(y) D, g' = sum sign(x - y) P(y) D
        g = g + abs(x - j * D) * prof(j)
        gp = gp + sign(1.0_rp, x - j * D) * merge(0.5_rp, 1.0_rp, abs(x - j * D) < 0.5_rp * D) &
                  * prof(j)
      end do
      g = g * D
      gp = gp * D
      gi(k) = 1.0_rp / g
      hoop(k) = gp / g
    end do
  end subroutine axis_weight_tables

  !> 1/g and g'/g at x [1/m] (tables of axis_weight_tables, linear between points; 1/|x| and
  !> 1/|x| beyond them), h the smoothing length.
  pure subroutine axis_weights(x, h, git, hoopt, gi, hoop)
    real(rp), intent(in) :: x, h, git(AXIS_TABLE_N), hoopt(AXIS_TABLE_N)
    real(rp), intent(out) :: gi, hoop
    real(rp) :: xi, t
    integer :: k
    xi = abs(x) / h
    if (xi >= AXIS_TABLE_X) then
      gi = 1.0_rp / abs(x)
      hoop = gi
    else
      t = xi * (AXIS_TABLE_N - 1) / AXIS_TABLE_X
      k = min(int(t) + 1, AXIS_TABLE_N - 1)
      t = t - (k - 1)
      gi = ((1.0_rp - t) * git(k) + t * git(k + 1)) / h
      hoop = ((1.0_rp - t) * hoopt(k) + t * hoopt(k + 1)) / h
    end if
  end subroutine axis_weights

  !> Tables of the ring kernel's derivatives (the rings pair, domain.axis_pair = "rings"; the
  !> pair itself is in loops/axisymmetric_loops.f90). The ring kernel is the 3D kernel averaged
  !> over the azimuth of ring b seen from a point of ring a,
  !>   Wr(s^2, p) = (1/pi) int_0^pi W3(d) dphi,  d^2 = s^2 + 4 p sin^2(phi/2),
  !> s^2 = (r_a - r_b)^2 + (z_a - z_b)^2, p = r_a r_b: the density sum_b m_b Wr is the 3D SPH
  !> density of the rings (no mirror images, no axis weight). With K(d) = W3'(d)/d:
  !>   Fs = dWr/ds^2 = (1/2pi) int K dphi,  Fp = dWr/dp = (1/pi) int K 2 sin^2(phi/2) dphi.
  !> For h = 1 on u = s^2/4 in [0, 1], v = p/(p + 1) in [0, 1]: gs = sqrt(p + 1) Fs,
  !> gp = (p + 1)^(3/2) Fp (finite as p -> infinity; v = 1 taken at p = 1e12). W3 is the 2D
  !> kernel's shape normalised in 3D (the integral of 4 pi q^2 f). Stored side by side,
  !> tab(1, i, j) = gs and tab(2, i, j) = gp at grid point (i, j), so that a lookup reads a
  !> cell's corners of both from two 32-byte pieces of a 1 MB table (ring_kernel_derivs).
  pure subroutine ring_kernel_tables(kind, tab)
    use sphjet_kinds, only: ip
    use sphjet_kernels, only: kernel_t, kernel_setup, kernel_eval
    integer(ip), intent(in) :: kind
    real(rp), intent(out) :: tab(2, RING_NU, RING_NV)
    integer, parameter :: NQ = 800, NR = 20000
    type(kernel_t) :: kern
    real(rp) :: norm3, q, w, f, s2, p, phimax, phi, dphi, d, sn, as, ap
    integer :: i, j, k
    kern = kernel_setup(kind, 1.0_rp)
    norm3 = 0.0_rp   ! int_0^2 4 pi q^2 W2(q) dq (midpoint): W3 = W2 / norm3
    do k = 1, NR
      q = (k - 0.5_rp) * 2.0_rp / NR
      call kernel_eval(kern, q, w, f)
      norm3 = norm3 + 4.0_rp * pi * q * q * w * (2.0_rp / NR)
    end do
    do j = 1, RING_NV
      if (j == RING_NV) then
        p = 1.0e12_rp
      else
        p = real(j - 1, rp) / (RING_NV - 1)
        p = p / (1.0_rp - p)
      end if
      do i = 1, RING_NU
        s2 = 4.0_rp * real(i - 1, rp) / (RING_NU - 1)
        as = 0.0_rp
        ap = 0.0_rp
        if (p > 0.0_rp) then
          phimax = 2.0_rp * asin(min(1.0_rp, sqrt(max(4.0_rp - s2, 0.0_rp)) / (2.0_rp * sqrt(p))))
        else
          phimax = pi
        end if
        dphi = phimax / NQ
        do k = 1, NQ
          phi = (k - 0.5_rp) * dphi
          sn = sin(0.5_rp * phi)
          d = sqrt(s2 + 4.0_rp * p * sn * sn)
          if (d >= 2.0_rp) cycle
          call kernel_eval(kern, max(d, 1.0e-9_rp), w, f)
          as = as + f * dphi
          ap = ap + f * 2.0_rp * sn * sn * dphi
        end do
        tab(1, i, j) = sqrt(p + 1.0_rp) * as / (2.0_rp * pi * norm3)
        tab(2, i, j) = (p + 1.0_rp)**1.5_rp * ap / (pi * norm3)
      end do
    end do
  end subroutine ring_kernel_tables

  !> Fs = dWr/ds^2 and Fp = dWr/dp of the ring kernel (ring_kernel_tables, bilinear in the
  !> cells of their grid) at s2 = s^2, p = r_a r_b [1/m^5], h the smoothing length.
  pure subroutine ring_kernel_derivs(s2, p, h, tab, fs, fp)
    real(rp), intent(in) :: s2, p, h, tab(2, RING_NU, RING_NV)
    real(rp), intent(out) :: fs, fp
    real(rp) :: u, v, pn, tu, tv, h5, a, b, sq
    integer :: i, j
    h5 = h**5
    u = min(s2 / (4.0_rp * h * h), 1.0_rp) * (RING_NU - 1)
    pn = p / (h * h)
    v = pn / (pn + 1.0_rp) * (RING_NV - 1)
    i = min(int(u) + 1, RING_NU - 1)
    j = min(int(v) + 1, RING_NV - 1)
    tu = u - (i - 1)
    tv = v - (j - 1)
    a = (1.0_rp - tu) * tab(1, i, j) + tu * tab(1, i + 1, j)
    b = (1.0_rp - tu) * tab(1, i, j + 1) + tu * tab(1, i + 1, j + 1)
    sq = sqrt(pn + 1.0_rp)
    fs = ((1.0_rp - tv) * a + tv * b) / (sq * h5)
    a = (1.0_rp - tu) * tab(2, i, j) + tu * tab(2, i + 1, j)
    b = (1.0_rp - tu) * tab(2, i, j + 1) + tu * tab(2, i + 1, j + 1)
    fp = ((1.0_rp - tv) * a + tv * b) / ((pn + 1.0_rp) * sq * h5)
  end subroutine ring_kernel_derivs

end module axisymmetric
