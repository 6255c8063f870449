!> Axisymmetric (r, z) SPH: the pointwise formulas (cases/axisymmetric/README.md gives the
!> equations, the derivation and the measurements). Particles live in the meridian half-plane,
!> x = r >= 0, the symmetry axis is the line x = 0; a particle stands for a ring and carries
!> its true 3D mass m = rho 2 pi r A (A its area in the meridian plane). The axis is closed by
!> mirror images (loops/sorted_state.f90): an image carries its source's mass, density and
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
            R_MIN_H, axis_weight_tables, axis_weights, AXIS_TABLE_N, axis_detection_factor

  !> Smallest radius used in 1/r, in units of h.
  real(rp), parameter :: R_MIN_H = 0.25_rp
  !> Smoothed-radius tables (axis_weight_tables): points, extent [h], grid of the sums [h].
  integer, parameter :: AXIS_TABLE_N = 201
  real(rp), parameter :: AXIS_TABLE_X = 2.0_rp, AXIS_GRID_D = 0.001_rp

contains

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

end module axisymmetric
