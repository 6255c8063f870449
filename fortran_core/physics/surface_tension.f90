!> CSF surface tension for a free surface, after Morris (2000) as the paper writes it
!> (DIGEST section 1, eqs 14-24). Pure per-pair and per-particle formulas only; the
!> traversals live in loops/surface_tension_loops.f90. With V_b = m_b / rho_b and
!> grad_a W_ab = F_ab (r_a - r_b):
!>   colour     C_a = sum_b V_b W_ab, self term V_a W(0) included               (eq 14)
!>   normal     n_a = sum_b V_b (C_b - C_a) grad_a W_ab; it points into the liquid (eq 18)
!>   filter     N_a = 1 if |n_a| > eps, eps = 0.01 / h                          (eq 20; the
!>              paper prints the inequality reversed)
!>   unit       nhat_a = n_a / |n_a| if N_a = 1, else 0                         (eq 21)
!>   curvature  kappa_a = sum_b min(N_a, N_b) V_b (nhat_b - nhat_a) . grad_a W_ab
!>                      / sum_b min(N_a, N_b) V_b W_ab                           (eq 23)
!>              the denominator includes the self term N_a V_a W(0): it is the Shepard sum of
!>              the particles whose normal is defined, so it is 1 where the whole support is
!>              covered and the formula then reduces to the plain SPH divergence; without the
!>              self term kappa would be too large by 1/(1 - V W(0)) (about 1.5 for Wendland
!>              at h = 1.3 dx) even in the interior of a resolved interface band.
!>   force      a_s,a = -(sigma / rho_a) kappa_a n_a                              (eq 24)
!>              with n the colour gradient of eq 18 (ST_DELTA_COLOUR, the paper), or, for a
!>              free surface, with n replaced by d = 2 sum_b V_b grad_a W_ab
!>              (ST_DELTA_PRESSURE, the default: a departure that makes the force balance the
!>              discrete pressure force at p = sigma/R; see loops/surface_tension_loops.f90)
!>   free-surface curvature (ST_DELTA_PRESSURE only; a departure from eq 23): the numerator of
!>              eq 23 over a first-order consistent denominator, the tangential component
!>              sum_b min(N_a,N_b) V_b (r_b - r_a).t_a (grad_a W_ab).t_a with t_a normal to
!>              nhat_a (1 in a full support, so it agrees with eq 23 there), which makes
!>              the divergence of nhat exact for a circle of particles: -1/r at radius r.
!>              The rows that carry the force lie inside the surface, at depth delta, so
!>              their -1/r exceeds the surface's -1/R by O(delta/R) (5% at R/dx = 20);
!>              kappa_s = kappa / (1 - kappa delta) moves it to the surface, with delta
!>              read from the colour: C(delta) of a flat surface (csf_depth_table). Eq 23's
!>              Shepard denominator instead under-normalises by a kernel-dependent factor
!>              that cancels that bias for Wendland but not for the cubic spline
!>              (cases/laplace_disc/README.md).
!>   surface band (surface_tension.curvature_normals = "surface_band"; free-surface curvature
!>              only): the sums of the numerator and of the tangential denominator of particle a
!>              take neighbour b only where b lies within CURV_BAND_H h of the surface (its
!>              depth from the colour, csf_depth, below CURV_BAND_H h); a itself may lie deeper.
!>              Deeper particles have a colour gradient that is the tail of a truncated kernel
!>              sum and follows the particles' spacing and, next to the axis, its mirror images
!>              more than the surface's shape: at a/dx = 5, h = 2 dx (the round jets) the rows 3
!>              and 3.5 spacings below a column's surface pass the normal filter, and with their
!>              normals in the sums the curvature answered a surface wave sin(kz) (ka = 2.1, every
!>              row shifted radially) with the wrong sign and 2-6 times the geometric k^2 eta, which
!>              made a column at rest unstable at about 900 1/s (cases/axisymmetric/README.md).
!>   surface fit (surface_tension.curvature = "surface_fit"; free-surface curvature only): the
!>              in-plane curvature of the parabola eta = c0 + c1 s + c2 s^2 fitted by weighted
!>              least squares (weights V_b W_ab, a itself with V_a W(0) when it is one of them)
!>              to the positions of the outer row's particles b (depth below FIT_DEPTH sqrt(V_b))
!>              in a's frame, s along the tangent t_a = (-nhat_z, nhat_x) and eta along nhat_a:
!>              kappa = -2 c2 / (1 + c1^2)^(3/2) at the fitted point x_a + c0 nhat_a of the outer
!>              row, moved to the surface by that point's depth, delta_a + c0 (c0 < 0 for a
!>              particle below the outer row). Axisymmetric: the azimuthal curvature takes the
!>              fitted curve's normal (nhat_a - c1 t_a, normalised) at the fitted point. A fit
!>              bent more sharply than a circle of one particle spacing is refused, as is one
!>              through fewer than three distinct s: the normals' curvature stays there
!>              (FIT_RADIUS_MIN). A curve through the particles does not change
!>              when they slide along it, where the divergence of their normals does: with the
!>              normals' divergence a column at rest of a/dx = 5, h = 2 dx grows waves of
!>              2.2-2.5 h from any disorder at about 300 1/s; with the fit none grows
!>              (cases/round_jet/README.md).
!> Sign check: for a 2D disc of radius R, nhat = -e_r, kappa = div nhat = -1/R and
!> a_s = (sigma / (rho R)) n points inward.
!> Capillary time-step limit (Brackbill et al. 1992; Morris 2000 eq 39):
!>   dt_st = 0.25 sqrt(rho h^3 / (2 pi sigma)); not part of the paper's eqs 30-32.
module surface_tension
  use sphjet_kinds, only: rp, pi
  implicit none
  private
  public :: csf_threshold, csf_normal_pair, csf_unit_normal, csf_curvature_pair, &
            csf_curvature, csf_acceleration, csf_dt, csf_surface_weight, &
            csf_tangential_pair, csf_depth_table, csf_depth, csf_surface_curvature, &
            csf_fit_point, csf_fit_curvature, depth_moved, N_FIT, FIT_DEPTH, &
            ST_DELTA_PRESSURE, ST_DELTA_COLOUR, DEPTH_TABLE_N, DEPTH_FACTOR_MIN, CURV_BAND_H

  !> Values of sph_params_t%surface_tension%delta (case key surface_tension.delta).
  integer, parameter :: ST_DELTA_PRESSURE = 0  !< "pressure_consistent": d = 2 sum_b V_b grad_a W_ab
  integer, parameter :: ST_DELTA_COLOUR = 1    !< "colour_gradient": n of eq 18 (paper eq 24)

  real(rp), parameter :: EPS_H = 0.01_rp      !< eps = EPS_H / h (eq 20)
  real(rp), parameter :: DT_ST_COEF = 0.25_rp  !< safety factor of the capillary limit
  !> Ramp of the surface weight of the pressure-consistent force, in |n| h (see
  !> csf_surface_weight): 0 below SURF_LO, 1 above SURF_HI.
  real(rp), parameter :: SURF_LO = 0.025_rp, SURF_HI = 0.075_rp

  !> Points of the flat-surface colour table C(delta), delta = 0 ... 2h.
  integer, parameter :: DEPTH_TABLE_N = 64
  !> Smallest tangential denominator accepted (its value in a full support is 1).
  real(rp), parameter :: TANGENTIAL_MIN = 0.05_rp
  !> Smallest 1 - kappa delta accepted by the depth correction (noise on concave spots).
  real(rp), parameter :: DEPTH_FACTOR_MIN = 0.5_rp
  !> Depth of the surface band whose normals enter the free-surface curvature with
  !> curvature_normals = "surface_band", in units of h.
  real(rp), parameter :: CURV_BAND_H = 1.0_rp
  !> The surface fit's sums per particle (csf_fit_point; the ninth counts the points), and the
  !> smallest determinant of its normal equations relative to the product of their diagonal's
  !> (about 1e-3 for points spread evenly over the support; 1e-9 leaves out only fits through
  !> fewer than three distinct s).
  integer, parameter :: N_FIT = 9
  real(rp), parameter :: FIT_DET_MIN = 1.0e-9_rp
  !> The smallest radius of curvature a fit may give, in units of the particle's spacing
  !> sqrt(V): a parabola bent more sharply than a circle through neighbours one spacing apart
  !> (60 degrees between them) is not drawn by the particles; it fits a few bunched points. Such
  !> a fit is refused and the normals' curvature taken. Where a froth of rings meets the axis
  !> (the 0.78 m/s round jet at d0/dx = 20, 55 ms) fits gave kappa h up to 4900 (normals: 2.3)
  !> and stopped the run with an axis ring at 15 m/s; refused, the run goes on. On a planar
  !> sheet of 10 spacings, whose true curvature is below 1/(30 dx), 0.7% of the fits bend more
  !> sharply than this (measured at 0.78 s of validation.jet.sheet_no_gravity).
  real(rp), parameter :: FIT_RADIUS_MIN = 1.0_rp
  !> The surface fit's points: the particles whose depth (csf_depth) is below FIT_DEPTH times their
  !> own spacing sqrt(V): the outer row, whose depth from the colour is about half a spacing (the
  !> next row's about 1.5). With the next row in the fit too, its points and the outer row's, at
  !> an offset, bend the parabola wherever the two rows' particles are spread unevenly along the
  !> surface (SurfaceFitIgnoresSlidingAlongTheSurface: kappa r_s sd 0.52 instead of 0.003 at
  !> h = 2 dx).
  real(rp), parameter :: FIT_DEPTH = 1.0_rp

contains

  !> eps of the normal filter (eq 20): 0.01 / h.
  pure function csf_threshold(h) result(eps)
    real(rp), intent(in) :: h
    real(rp) :: eps
    eps = EPS_H / h
  end function csf_threshold

  !> Eq 18 for one pair (a, b), g = grad_a W_ab: the contribution to n_a is
  !> V_b (C_b - C_a) g, and to n_b is V_a (C_a - C_b) grad_b W_ba = V_a (C_b - C_a) g.
  pure subroutine csf_normal_pair(va, vb, ca, cb, gx, gz, nax, naz, nbx, nbz)
    real(rp), intent(in) :: va, vb, ca, cb, gx, gz
    real(rp), intent(out) :: nax, naz, nbx, nbz
    real(rp) :: dc
    dc = cb - ca
    nax = vb * dc * gx
    naz = vb * dc * gz
    nbx = va * dc * gx
    nbz = va * dc * gz
  end subroutine csf_normal_pair

  !> The two sums of eq 23 for one pair, g = grad_a W_ab, fa, fb the filter flags N:
  !> a gets min(N_a,N_b) V_b (nhat_b - nhat_a) . g and min(N_a,N_b) V_b W; b gets
  !> min(N_a,N_b) V_a (nhat_a - nhat_b) . (-g) (the same dot product) and min(N_a,N_b) V_a W.
  pure subroutine csf_curvature_pair(fa, fb, va, vb, nhxa, nhza, nhxb, nhzb, gx, gz, w, &
                                     numa, dena, numb, denb)
    real(rp), intent(in) :: fa, fb, va, vb, nhxa, nhza, nhxb, nhzb, gx, gz, w
    real(rp), intent(out) :: numa, dena, numb, denb
    real(rp) :: f, d
    f = min(fa, fb)
    d = f * ((nhxb - nhxa) * gx + (nhzb - nhza) * gz)
    numa = vb * d
    numb = va * d
    dena = f * vb * w
    denb = f * va * w
  end subroutine csf_curvature_pair

  !> The tangential denominator of the free-surface curvature for one pair, d = r_a - r_b,
  !> f = F_ab (grad_a W_ab = f d), t = nhat rotated by 90 degrees: a gets
  !> min(N_a,N_b) V_b (r_b - r_a).t_a (f d).t_a = -min(N) V_b f (d.t_a)^2 (>= 0, f < 0), b the
  !> same with V_a and t_b.
  pure subroutine csf_tangential_pair(fa, fb, va, vb, nhxa, nhza, nhxb, nhzb, dx, dz, f, &
                                      tana, tanb)
    real(rp), intent(in) :: fa, fb, va, vb, nhxa, nhza, nhxb, nhzb, dx, dz, f
    real(rp), intent(out) :: tana, tanb
    real(rp) :: m, da, db
    m = -min(fa, fb) * f
    da = -dx * nhza + dz * nhxa   ! d . t_a, t_a = (-nhz, nhx)
    db = -dx * nhzb + dz * nhxb
    tana = m * vb * da * da
    tanb = m * va * db * db
  end subroutine csf_tangential_pair

  !> The colour of a particle at depth delta below a flat free surface in a continuum of
  !> liquid, C(delta) = 1/2 + int_0^delta P(y) dy with P(y) = int W(sqrt(x^2 + y^2)) dx the
  !> kernel's profile across the surface; tab(k) at delta = 2h (k-1)/(DEPTH_TABLE_N-1).
  !> C depends on delta/h and the kernel kind only, so the table is built with h = 1 and
  !> serves every h (callers keep one per kind). Midpoint sums of 100 x 100 cells over the
  !> quarter support (relative error about 1e-4).
  pure subroutine csf_depth_table(kind, tab)
    use sphjet_kinds, only: ip
    use sphjet_kernels, only: kernel_t, kernel_setup, kernel_profile
    integer(ip), intent(in) :: kind
    real(rp), intent(out) :: tab(DEPTH_TABLE_N)
    integer, parameter :: NQ = 100
    type(kernel_t) :: kern
    real(rp) :: prof(NQ), ymid, cell, acc, delta, ycut
    integer :: j, k
    kern = kernel_setup(kind, 1.0_rp)
    cell = 2.0_rp * kern%h / NQ
    do j = 1, NQ          ! P at the midpoints of the y cells
      ymid = (j - 0.5_rp) * cell
      prof(j) = kernel_profile(kern, ymid, NQ)
    end do
    do k = 1, DEPTH_TABLE_N
      delta = 2.0_rp * kern%h * (k - 1) / (DEPTH_TABLE_N - 1)
      acc = 0.0_rp
      do j = 1, NQ
        ycut = min(max(delta - (j - 1) * cell, 0.0_rp), cell)   ! part of cell j below delta
        acc = acc + prof(j) * ycut
      end do
      tab(k) = 0.5_rp + acc
    end do
  end subroutine csf_depth_table

  !> Depth below the surface from the colour, inverting the table (linear between points):
  !> 0 for C <= C(0) = 1/2, 2h for C >= C(2h) (the interior: answered without the search).
  pure function csf_depth(c, tab, h) result(delta)
    real(rp), intent(in) :: c, tab(DEPTH_TABLE_N), h
    real(rp) :: delta, t
    integer :: k
    if (c <= tab(1)) then
      delta = 0.0_rp
      return
    end if
    if (c >= tab(DEPTH_TABLE_N)) then
      delta = 2.0_rp * h
      return
    end if
    do k = 2, DEPTH_TABLE_N
      if (c <= tab(k)) then
        t = (c - tab(k - 1)) / max(tab(k) - tab(k - 1), tiny(1.0_rp))
        delta = 2.0_rp * h * (k - 2 + t) / (DEPTH_TABLE_N - 1)
        return
      end if
    end do
    delta = 2.0_rp * h   ! not reached: tab is increasing and c < tab(DEPTH_TABLE_N)
  end function csf_depth

  !> Free-surface curvature from the numerator of eq 23, the tangential denominator tden and the
  !> depth: kappa = num / tden, then kappa / (1 - kappa delta) (the factor kept >= 1/2);
  !> 0 without a valid normal or with a denominator below TANGENTIAL_MIN.
  !> Adds the point (s, eta) with weight om to a particle's least-squares sums of the surface
  !> fit: fit(1:8) = sum om (1, s, s^2, s^3, s^4, eta, eta s, eta s^2), and counts it in fit(9)
  !> when om > 0. (rx, rz) = the point minus the particle; (nx, nz) the particle's unit normal.
  pure subroutine csf_fit_point(om, rx, rz, nx, nz, fit)
    real(rp), intent(in) :: om, rx, rz, nx, nz
    real(rp), intent(inout) :: fit(N_FIT)
    real(rp) :: s, e
    s = -rx * nz + rz * nx
    e = rx * nx + rz * nz
    fit(1:8) = fit(1:8) + om * [1.0_rp, s, s * s, s**3, s**4, e, e * s, e * s * s]
    if (om > 0.0_rp) fit(9) = fit(9) + 1.0_rp
  end subroutine csf_fit_point

  !> The fitted parabola's in-plane curvature kin and, through nrx, the radial part of its unit
  !> normal at the fitted point and that point's offset c0 along the normal. ok = .false. (and
  !> nothing set) when the points do not determine a parabola (fewer than three distinct s), when
  !> they are fewer than points_min (case key surface_tension.fit_points_min; sparse = .true.
  !> then, else .false.), or when it bends more sharply than a circle of FIT_RADIUS_MIN spacings
  !> (spacing: the particle's, sqrt(V)). Three points determine the parabola and no more: a row
  !> at the edge of the kernel's reach of the surface sees the outer row over a chord of about
  !> three points, and on a lattice stretched along the axis (a falling jet sped up 1.35 times)
  !> their parabola gave that row a mean curvature of the wrong sign (cases/round_jet/README.md,
  !> "The jets' own capillary growth").
  pure subroutine csf_fit_curvature(fit, nx, nz, spacing, points_min, kin, nrx, c0, ok, sparse)
    real(rp), intent(in) :: fit(N_FIT), nx, nz, spacing
    integer, intent(in) :: points_min
    real(rp), intent(inout) :: kin, nrx, c0
    logical, intent(out) :: ok, sparse
    real(rp) :: m(3, 3), r(3), det, c1, c2, mx, mz, kfit
    sparse = .false.
    m = reshape([fit(1), fit(2), fit(3), fit(2), fit(3), fit(4), fit(3), fit(4), fit(5)], [3, 3])
    r = fit(6:8)
    det = det3(m(:, 1), m(:, 2), m(:, 3))
    ok = abs(det) > FIT_DET_MIN * fit(1) * fit(3) * fit(5)
    if (.not. ok) return
    sparse = fit(9) < points_min
    ok = .not. sparse
    if (.not. ok) return
    c1 = det3(m(:, 1), r, m(:, 3)) / det
    c2 = det3(m(:, 1), m(:, 2), r) / det
    kfit = -2.0_rp * c2 / (1.0_rp + c1 * c1)**1.5_rp
    ok = abs(kfit) * FIT_RADIUS_MIN * spacing <= 1.0_rp
    if (.not. ok) return
    kin = kfit
    c0 = det3(r, m(:, 2), m(:, 3)) / det
    mx = nx + c1 * nz      ! nhat - c1 t, t = (-nz, nx)
    mz = nz - c1 * nx
    nrx = mx / sqrt(mx * mx + mz * mz)
  end subroutine csf_fit_curvature

  pure real(rp) function det3(u, v, w)
    real(rp), intent(in) :: u(3), v(3), w(3)
    det3 = u(1) * (v(2) * w(3) - v(3) * w(2)) - v(1) * (u(2) * w(3) - u(3) * w(2)) &
           + w(1) * (u(2) * v(3) - u(3) * v(2))
  end function det3

  pure elemental function csf_surface_curvature(num, tden, flag, delta) result(kappa)
    real(rp), intent(in) :: num, tden, flag, delta
    real(rp) :: kappa
    if (flag > 0.0_rp .and. tden > TANGENTIAL_MIN) then
      kappa = num / tden
      kappa = kappa / max(DEPTH_FACTOR_MIN, 1.0_rp - kappa * delta)
    else
      kappa = 0.0_rp
    end if
  end function csf_surface_curvature

  !> Filter and unit normal (eqs 20-21): flag = 1 and nhat = n/|n| if |n| > eps, else 0.
  pure elemental subroutine csf_unit_normal(nx, nz, eps, nhx, nhz, flag)
    real(rp), intent(in) :: nx, nz, eps
    real(rp), intent(out) :: nhx, nhz, flag
    real(rp) :: mag
    mag = sqrt(nx * nx + nz * nz)
    if (mag > eps) then
      nhx = nx / mag
      nhz = nz / mag
      flag = 1.0_rp
    else
      nhx = 0.0_rp
      nhz = 0.0_rp
      flag = 0.0_rp
    end if
  end subroutine csf_unit_normal

  !> Curvature from the two sums of eq 23; 0 where the particle has no valid normal (the
  !> denominator then holds no self term and no neighbour) or the denominator vanishes.
  pure elemental function csf_curvature(num, den, flag) result(kappa)
    real(rp), intent(in) :: num, den, flag
    real(rp) :: kappa
    if (flag > 0.0_rp .and. den > 0.0_rp) then
      kappa = num / den
    else
      kappa = 0.0_rp
    end if
  end function csf_curvature

  !> Eq 24: a_s = -(sigma / rho) kappa d, d the interface delta times its normal: the colour
  !> gradient n in the paper, 2 sum_b V_b grad_a W_ab for a free surface (see the loops).
  pure elemental subroutine csf_acceleration(sigma, rho, kappa, nx, nz, ax, az)
    real(rp), intent(in) :: sigma, rho, kappa, nx, nz
    real(rp), intent(out) :: ax, az
    real(rp) :: s
    s = -sigma * kappa / rho
    ax = s * nx
    az = s * nz
  end subroutine csf_acceleration

  !> Weight of the pressure-consistent force (ST_DELTA_PRESSURE only) at a particle with colour
  !> gradient n: w = clamp((|n| h - SURF_LO) / (SURF_HI - SURF_LO), 0, 1). The filter of eq 20
  !> (|n| > 0.01 / h) sits at the noise level of a free-surface colour function: on a ring disc
  !> the two outer rows have |n| h = 0.13 and the third 0.017, but so have particles near
  !> the centre where the arrangement is irregular (0.017-0.024), and their curvature from
  !> eq 23 (neighbours with random unit normals) is of order 1/h. With the delta d of the
  !> pressure-consistent force, nonzero wherever the arrangement is irregular, such a particle
  !> gets a spurious force about R/h times the pressure noise it already has, which drove an
  !> instability from the centre of a Laplace drop within 0.06 s. The weight keeps the force on
  !> the outer rows and off the interior. Not applied to the paper's force (ST_DELTA_COLOUR),
  !> which is eq 24 as printed; there n itself is small where |n| is.
  pure elemental function csf_surface_weight(nx, nz, h) result(wt)
    real(rp), intent(in) :: nx, nz, h
    real(rp) :: wt
    wt = (sqrt(nx * nx + nz * nz) * h - SURF_LO) / (SURF_HI - SURF_LO)
    wt = min(1.0_rp, max(0.0_rp, wt))
  end function csf_surface_weight

  !> Capillary time-step limit 0.25 sqrt(rho h^3 / (2 pi sigma)); huge when sigma = 0.
  pure function csf_dt(rho, h, sigma) result(dt)
    real(rp), intent(in) :: rho, h, sigma
    real(rp) :: dt
    if (sigma > 0.0_rp) then
      dt = DT_ST_COEF * sqrt(rho * h**3 / (2.0_rp * pi * sigma))
    else
      dt = huge(1.0_rp)
    end if
  end function csf_dt

  !> A principal curvature k of a particle's row moved to the surface at depth delta:
  !> k / (1 - k delta), the factor kept >= DEPTH_FACTOR_MIN as in csf_surface_curvature (whose tangential
  !> denominator test has already zeroed an invalid k).
  pure elemental function depth_moved(k, delta) result(ks)
    real(rp), intent(in) :: k, delta
    real(rp) :: ks
    ks = k / max(DEPTH_FACTOR_MIN, 1.0_rp - k * delta)
  end function depth_moved

end module surface_tension
