!> CSF surface tension (Morris 2000; paper eqs 14-24) over the sorted particles: three pair
!> sweeps of the common traversal (colour, then normal, then curvature) with per-particle
!> steps between them, and the acceleration a_s = -(sigma/rho) kappa n added to the pair
!> accelerations (sorted order) before rates.f90 scatters them. The formulas are in
!> physics/surface_tension.f90. Like every traversal here, each particle receives its
!> contributions in a fixed order, so the result is bitwise independent of the thread count.
!>
!> Boundary particles do not enter: colour, normal and curvature are sums over fluid
!> neighbours only, boundary particles get C = n = kappa = 0 and no force. A wall therefore
!> counts as "not liquid": fluid along a flat wall has a colour gradient pointing away from the
!> wall but (the normal being uniform along the wall) no curvature and hence no force, and
!> at a wall's end (a nozzle lip) the free surface meets the wall as a non-wetting contact
!> (no adhesion term). Counting boundary particles as liquid instead would make the outer
!> faces of a thin nozzle wall look like a liquid surface and pull fluid inside the nozzle
!> towards them. Walls hold the fluid through the boundary scheme only.
!>
!> Axisymmetric mode: where the free surface is (the filter of eq 20 and the surface weight)
!> is decided by the gradient of a second colour, (1/g_a) sum_b (m_b / (2 pi rho_b)) W_ab, the
!> Shepard sum of the mode's density (axisymmetric.f90), with its radial part damped within 2h
!> of the axis (axis_detection_factor). The planar colour sum_b (m_b / rho_b) W_ab weighs each
!> ring by its planar area m / (2 pi r rho), which changes by dr / r when a ring near the axis
!> moves by dr: in a Rayleigh-Plateau cylinder at nu = 1e-5 that colour drifted to 0.89-1.43
!> on the two rows next to the axis, flagged interior rings as surface with a curvature
!> n_r / r ~ 1/h, and stopped the run there (cases/axisymmetric/README.md). The normal's
!> direction, the curvature and the depth still come from the planar colour: with the second
!> colour in those too, a sphere at rest held 0.63-0.94 of its Laplace pressure, since that
!> colour is 6% high on the lattice row next to the axis, where a sphere's poles are.
module surface_tension_loops
  use sphjet_kinds, only: rp, KERNEL_WENDLAND, GEOM_AXISYMMETRIC, AXIS_PAIR_RINGS, &
                          RINGS_CURVATURE_MEAN, CURV_NORMALS_BAND, CURVATURE_SURFACE_FIT
  use axisymmetric, only: azimuthal_curvature, mass_per_radian, axis_detection_factor
  use axisymmetric_loops, only: axis_weights_of
  use sphjet_types, only: sph_params_t, state_t
  use sphjet_kernels, only: kernel_t, kernel_eval, kernel_w0
  use sorted_state, only: sorted_t, R_AX, R_AZ
  use particle_images, only: copy_to_images
  use free_body_loops, only: bodies_of, balance_free_bodies, thin_free_rings
  use omp_team, only: team_work_t, in_team
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_ANY_FLUID, SWEEP_KEEP, &
                       SWEEP_REUSE
  use surface_tension, only: csf_threshold, csf_unit_normal, csf_curvature, csf_acceleration, &
                             csf_surface_weight, csf_depth_table, csf_depth, csf_surface_curvature, &
                             ST_DELTA_COLOUR, DEPTH_TABLE_N, CURV_BAND_H, csf_fit_curvature, N_FIT, &
                             FIT_DEPTH, depth_moved
  use csf_pair_sums, only: NG_NX, NG_NZ, NG_GX, NG_GZ, N_NG, colour_pairs, normal_pairs, &
                           curvature_pairs, surface_fit_pairs, band_curvature_pairs, surface_mean_pairs
  implicit none
  private
  public :: surface_tension_rates

  !> The delta of eq 24, chosen at run time by prm%surface_tension%delta (case key surface_tension.delta):
  !>  ST_DELTA_COLOUR (1, "colour_gradient"): a_s = -(sigma/rho) kappa n with n the colour
  !>    gradient of eq 18, exactly as the paper prints it. Eqs 14-24 come from two-phase CSF
  !>    (Morris 2000), where the colour jumps 1 -> 0 across particles on both sides of the
  !>    interface. At a free surface there are no particles outside, so only the liquid side of
  !>    the smoothed jump is on particles and the difference form of eq 18 shrinks it further:
  !>    a static disc is in equilibrium at a pressure of only 0.11-0.14 sigma/R
  !>    (test_core_surface_tension, LaplaceBalanceOfStaticDisc), i.e. the paper's force
  !>    underestimates sigma by a factor 7-9 at a free surface.
  !>  ST_DELTA_PRESSURE (0, "pressure_consistent", the default): n in eq 24 only is replaced by
  !>    d_a = 2 sum_b V_b grad_a W_ab, the kernel-truncation vector (points into the liquid,
  !>    zero inside a full support) doubled: the symmetric pressure force of rates.f90 on a
  !>    particle in a uniform pressure p is -(p/rho) d_a, so a_s = -(sigma/rho) kappa d_a
  !>    balances exactly the uniform pressure p = -sigma kappa = sigma/R of the Laplace law,
  !>    whatever the particle arrangement. The force is applied with the surface weight of
  !>    csf_surface_weight (1 on the outer rows, 0 in the interior where |n| h < 0.025).
  !>    Its curvature is the free-surface curvature of csf_surface_curvature: eq 23's numerator
  !>    over a first-order consistent (tangential) denominator, moved from the particle's row
  !>    to the surface by the depth read from the colour.
  !> Colour, normal and filter (eqs 14-21) are the paper's in both, and so is the curvature
  !> (eq 23) of ST_DELTA_COLOUR; the fields written out are n and the curvature used. Other
  !> values are rejected by the C entry points (params_ok).

  integer, parameter :: PASS_COLOUR = 1, PASS_NORMAL = 2, PASS_CURVATURE = 3, &
                        PASS_SURFACE_CURVATURE = 4, PASS_SURFACE_MEAN = 5, PASS_BAND_CURVATURE = 6, &
                        PASS_SURFACE_FIT = 7

  !> Flat-surface colour tables C(delta/h) of csf_depth_table, built once per kernel kind
  !> (indexed by the kind; KERNEL_WENDLAND is the largest) on first use.
  real(rp), save :: depth_cache(DEPTH_TABLE_N, KERNEL_WENDLAND)
  logical, save :: depth_cached(KERNEL_WENDLAND) = .false.

  !> Per-particle fields in sorted order.
  type :: csf_work_t
    real(rp), allocatable :: v(:), c(:), nhx(:), nhz(:), flag(:), num(:), den(:)
    !> the normal sums ng(NG_*, k) side by side (normal_pairs adds a pair's four to b's slot):
    !> n and the free-surface delta's sum_b V_b (g_a + g_b) grad_a W_ab
    real(rp), allocatable :: ng(:, :)
    real(rp), allocatable :: tden(:)       !< tangential denominator (free-surface curvature)
    !> axisymmetric only: the weights of the free-surface delta's pair sums (normal_pairs),
    !> 1/g with m / (2 pi rho) for V (the weights of its pressure pair; planar: 1/2 and m/rho)
    real(rp), allocatable :: vmu(:), gi(:)
    !> axisymmetric only: the colour (1/g_a) sum_b (m_b / (2 pi rho_b)) W_ab of the mode's
    !> density and its gradient, which decide where the free surface is (see below)
    real(rp), allocatable :: c2(:), n2x(:), n2z(:)
    !> the rings pair with surface_tension.rings_curvature = "neighbour_mean" (the default) only
    !> (surface_mean_pairs): each particle's own curvature and its weight in the mean (its force
    !> weight, or 0 where its surface fit had fewer than fit_points_min points)
    real(rp), allocatable :: kown(:), wt(:)
    !> curvature_normals = "surface_band" only: 1 where the particle passes the filter and lies
    !> within CURV_BAND_H h of the surface, else 0 (band_curvature_pairs)
    real(rp), allocatable :: band(:)
    !> surface_tension.curvature = "surface_fit" only: 1 where the particle passes the filter and
    !> lies in the outer row (depth below FIT_DEPTH sqrt(V)), else 0, and each particle's
    !> least-squares sums of the surface fit, fit(1:N_FIT, k) (csf_fit_point)
    real(rp), allocatable :: outer(:), fit(:, :)
  end type csf_work_t

  !> The CSF pair loop body: which pass, and the per-particle fields it reads and sums into.
  type, extends(pair_body_t) :: csf_body_t
    integer :: pass = PASS_COLOUR
    logical :: axi = .false.
    type(csf_work_t), pointer :: wk => null()
  contains
    procedure :: visit => csf_visit
  end type csf_body_t

  !> The per-particle loops between the passes (in_team): which = SELF_TERMS (colour self
  !> terms, zero sums), UNIT_NORMAL (filter and unit normal) or FORCE (curvature and
  !> acceleration).
  integer, parameter :: SELF_TERMS = 1, UNIT_NORMAL = 2, FORCE = 3
  type, extends(team_work_t) :: csf_loops_t
    type(sph_params_t) :: prm
    type(kernel_t) :: kern
    type(sorted_t), pointer :: s => null()
    type(csf_work_t), pointer :: wk => null()
    real(rp), pointer :: kappa(:) => null()
    real(rp) :: w0 = 0.0_rp, eps = 0.0_rp
    logical :: colour_delta = .false., axi = .false.
  contains
    procedure :: run => csf_particle_loops
  end type csf_loops_t

contains

  !> Adds a_s (sorted order) to s%rate (rows R_AX, R_AZ) and stores colour, normal n
  !> (unnormalised) and curvature in particle order in st%colour, st%st_nx, st%st_nz,
  !> st%kappa when those arrays are present (0 for boundary and inactive particles). s must
  !> hold the gathered state (gather_sorted). Nothing is done when sigma = 0 and no field
  !> array is present. kept (default .false.): the pairs of the rates sweep at these
  !> positions are kept in s (pair_sweep with SWEEP_KEEP, PAIRS_ANY_FLUID); the colour pass
  !> visits them instead of finding the pairs and evaluating the kernel again.
  subroutine surface_tension_rates(prm, kern, st, s, kept)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout) :: st
    type(sorted_t), intent(inout), target :: s
    logical, intent(in), optional :: kept
    type(csf_work_t), target :: wk
    real(rp) :: w0, eps
    real(rp), allocatable, target :: kappa(:)
    real(rp), allocatable :: hoop(:), a0(:, :)   ! a0: the rates before the CSF force (free bodies)
    integer, allocatable :: body(:)              ! the free bodies (free_body_loops.f90), once a call
    logical, allocatable :: held(:)
    type(csf_loops_t) :: loops
    integer :: n, k
    logical :: colour_delta, axi, reuse, surface_mean

    reuse = .false.
    if (present(kept)) reuse = kept
    n = s%n
    if (.not. (prm%surface_tension%sigma > 0.0_rp) .and. .not. associated(st%colour)) return
    allocate(wk%v(n), wk%c(n), wk%ng(N_NG, n), wk%nhx(n), wk%nhz(n), wk%flag(n), &
             wk%num(n), wk%den(n), wk%tden(n), kappa(n))
    w0 = kernel_w0(kern)
    eps = csf_threshold(prm%numerics%h)
    colour_delta = prm%surface_tension%delta == ST_DELTA_COLOUR   ! chosen outside the loops
    axi = prm%geometry%kind == GEOM_AXISYMMETRIC
    loops = csf_loops_t(prm=prm, kern=kern, s=s, wk=wk, kappa=kappa, w0=w0, eps=eps, &
                        colour_delta=colour_delta, axi=axi)

    surface_mean = prm%geometry%kind == GEOM_AXISYMMETRIC .and. prm%geometry%axis_pair == AXIS_PAIR_RINGS &
                   .and. prm%surface_tension%delta /= ST_DELTA_COLOUR &
                   .and. prm%surface_tension%rings_curvature == RINGS_CURVATURE_MEAN
    if (surface_mean) allocate(wk%kown(n), wk%wt(n), source=0.0_rp)
    if (axi) then   ! the free-surface delta follows the axisymmetric pressure pair
      allocate(wk%vmu(n), wk%gi(n), hoop(n), wk%c2(n), wk%n2x(n), wk%n2z(n))
      call axis_weights_of(kern, s%x(1:n), wk%gi, hoop)
      wk%vmu = mass_per_radian(s%m(1:n), s%x(1:n), prm%numerics%h) / s%rho(1:n)
    end if

    ! colour (eq 14), self term included
    call in_team(loops, SELF_TERMS)
    call sweep(PASS_COLOUR, kern, s, wk, reuse, axi)
    if (axi) wk%c2 = wk%c2 * wk%gi
    ! image slots (axis, periodic z) take their source's sums: their own lack the neighbours
    ! beyond the image band (particle_images.f90); nothing to do without images
    if (s%n > s%n_real) then
      call copy_to_images(s, wk%c, .false.)
      if (axi) call copy_to_images(s, wk%c2, .false.)
    end if

    ! normal (eq 18), then filter and unit normal (eqs 20-21)
    call sweep(PASS_NORMAL, kern, s, wk, .true., axi)
    if (axi) then   ! d_a = sum_b (m_b / (2 pi rho_b)) (1/g_a + 1/g_b) grad_a W_ab - (g'_a/g_a) e_r
      wk%ng(NG_GX, :) = wk%ng(NG_GX, :) - sign(1.0_rp, s%x(1:n)) * hoop
      if (prm%geometry%axis_pair == AXIS_PAIR_RINGS) then
        ! the rings pair's own, from the rates of this evaluation (axisymmetric_rates); the
        ! fields-only call of the initial state (sph_surface_tension_fields, no acceleration
        ! asked for) has no rates: no force
        wk%ng(NG_GX:NG_GZ, :) = 0.0_rp
        if (allocated(s%axi_dx)) then
          if (size(s%axi_dx) >= n) then
            wk%ng(NG_GX, :) = s%axi_dx(1:n)
            wk%ng(NG_GZ, :) = s%axi_dz(1:n)
          end if
        end if
      end if
      ! the radial part damped next to the axis (axis_detection_factor)
      wk%n2x = wk%n2x * wk%gi * axis_detection_factor(s%x(1:n), prm%numerics%h)
      wk%n2z = wk%n2z * wk%gi
    end if
    if (s%n > s%n_real) then
      call copy_to_images(s, wk%ng(NG_NX, :), .true.)
      call copy_to_images(s, wk%ng(NG_NZ, :), .false.)
      call copy_to_images(s, wk%ng(NG_GX, :), .true.)
      call copy_to_images(s, wk%ng(NG_GZ, :), .false.)
      if (axi) then
        call copy_to_images(s, wk%n2x, .true.)
        call copy_to_images(s, wk%n2z, .false.)
      end if
    end if
    call in_team(loops, UNIT_NORMAL)

    if (prm%surface_tension%free_bodies /= 0 .or. prm%surface_tension%thin_rings /= 0) call bodies_of(prm, s, body, held)
    ! curvature (eq 23) and acceleration (eq 24)
    if (colour_delta) then
      call sweep(PASS_CURVATURE, kern, s, wk, .true., axi)
    else
      !$omp critical (csf_depth_cache)
      if (.not. depth_cached(kern%kind)) then
        call csf_depth_table(kern%kind, depth_cache(:, kern%kind))
        depth_cached(kern%kind) = .true.
      end if
      !$omp end critical (csf_depth_cache)
      if (prm%surface_tension%curvature_normals == CURV_NORMALS_BAND) then
        ! the normals within CURV_BAND_H h of the surface (physics/surface_tension.f90); the
        ! image slots have their sources' colour and filter flag already
        allocate(wk%band(n))
        !$omp parallel do schedule(static)
        do k = 1, n
          wk%band(k) = merge(wk%flag(k), 0.0_rp, &
                             csf_depth(wk%c(k), depth_cache(:, kern%kind), prm%numerics%h) &
                             < CURV_BAND_H * prm%numerics%h)
        end do
        !$omp end parallel do
        call sweep(PASS_BAND_CURVATURE, kern, s, wk, .true., axi)
      else
        call sweep(PASS_SURFACE_CURVATURE, kern, s, wk, .true., axi)
      end if
      if (prm%surface_tension%curvature == CURVATURE_SURFACE_FIT) then
        ! the surface fit (physics/surface_tension.f90) through the outer row, each of whose
        ! particles is also its own point; the normals' curvature above stays where it fails
        allocate(wk%outer(n), wk%fit(N_FIT, n))
        !$omp parallel do schedule(static)
        do k = 1, n
          wk%outer(k) = merge(wk%flag(k), 0.0_rp, &
                              csf_depth(wk%c(k), depth_cache(:, kern%kind), prm%numerics%h) &
                              < FIT_DEPTH * sqrt(wk%v(k)))
          wk%fit(:, k) = 0.0_rp
          wk%fit(1, k) = wk%outer(k) * wk%v(k) * w0
          wk%fit(N_FIT, k) = wk%outer(k)   ! the self point counted
        end do
        !$omp end parallel do
        if (allocated(body) .and. prm%surface_tension%thin_rings /= 0) &   ! no fit points (free_body_loops.f90)
          call thin_free_rings(prm, s, wk%v, body, held, wk%outer, wk%fit)
        call sweep(PASS_SURFACE_FIT, kern, s, wk, .true., axi)
      end if
    end if
    if (prm%surface_tension%free_bodies /= 0) a0 = s%rate(R_AX:R_AZ, 1:n)
    call in_team(loops, FORCE)
    if (surface_mean) call surface_mean_force(prm, kern, st, s, wk, kappa, w0, axi)
    if (allocated(a0) .and. allocated(body)) call balance_free_bodies(prm, s, a0, axi, body, held)
    if (prm%numerics%shifting > 0.0_rp) call shifting_velocity(prm, st, s, wk, axi)

    call fields_to_particles(st, s, wk, kappa)

  end subroutine surface_tension_rates

  !> The rings pair (surface_tension.rings_curvature = "neighbour_mean"): the force of every
  !> weighted row with the weighted mean curvature of its neighbours, kappa_a = sum_b w_b
  !> kappa_b V_b W_ab / sum_b w_b V_b W_ab (b = a included; w the force weight,
  !> csf_surface_weight): the rows within 2h of the surface (four at h = 2 dx) balance one
  !> pressure, the surface's, where each row's own curvature from its own normals goes wrong
  !> next to a pole (cases/axisymmetric/README.md). A particle whose surface fit was refused for
  !> too few points (surface_tension.fit_points_min) enters no mean, its own included (w 0 in
  !> the sums), and takes its neighbours' mean; the force weight is csf_surface_weight's, taken
  !> again here.
  subroutine surface_mean_force(prm, kern, st, s, wk, kappa, w0, axi)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(in) :: st
    type(sorted_t), intent(inout) :: s
    type(csf_work_t), intent(inout), target :: wk
    real(rp), intent(inout) :: kappa(:)
    real(rp), intent(in) :: w0
    logical, intent(in) :: axi
    integer :: n, k
    real(rp) :: ax, az, wf
    n = s%n
    if (s%n > s%n_real) then
      call copy_to_images(s, wk%kown, .false.)
      call copy_to_images(s, wk%wt, .false.)
    end if
    !$omp parallel do schedule(static)
    do k = 1, n
      wk%num(k) = wk%wt(k) * wk%kown(k) * wk%v(k) * w0
      wk%den(k) = wk%wt(k) * wk%v(k) * w0
    end do
    !$omp end parallel do
    call sweep(PASS_SURFACE_MEAN, kern, s, wk, .true., axi)
    !$omp parallel do schedule(static) private(ax, az, wf)
    do k = 1, n
      if (wk%flag(k) == 0.0_rp .or. s%grid%order(k) > st%n) cycle
      if (wk%den(k) > 0.0_rp) kappa(k) = wk%num(k) / wk%den(k)
      if (s%fluid(k) .and. prm%surface_tension%sigma > 0.0_rp) then
        wf = csf_surface_weight(wk%n2x(k), wk%n2z(k), prm%numerics%h)   ! the force weight
        call csf_acceleration(prm%surface_tension%sigma, s%rho(k), kappa(k), wf * wk%ng(NG_GX, k), &
                              wf * wk%ng(NG_GZ, k), ax, az)
        s%rate(R_AX, k) = s%rate(R_AX, k) + ax
        s%rate(R_AZ, k) = s%rate(R_AZ, k) + az
      end if
    end do
    !$omp end parallel do
  end subroutine surface_mean_force

  !> Particle shifting (numerics.shifting = A; Lind et al. 2012, Sun et al.'s velocity form):
  !> each fluid slot drifts with u_s = -A h (c0/10) grad C added to its XSPH velocity
  !> (sorted_state.f90, add_shift), grad C = sum_b V_b grad_a W_ab the kernel's truncation
  !> vector: the CSF free-surface delta (wk%ng NG_GX, NG_GZ; axisymmetric 2 grad C with the rings'
  !> weights), zero inside a whole support on an even arrangement. Where the surface cuts the
  !> kernel (colour, axisymmetric c2, below SHIFT_WHOLE) only its part normal to the colour's
  !> gradient is kept, so the surface is not pushed out: on a flat surface at h = 2 dx the two
  !> outer rows (colour 0.69, 0.93); the third (0.997) keeps a small outward shift. A ring closer
  !> to the axis than h/2 shifts along the axis only: radially, the nozzle's innermost ring went
  !> from dx/2 to 0.6-0.9 dx and the round jet's floor C from 17.2 to 9.5
  !> (cases/round_jet/README.md, "Gravity along the jet"). No Taylor correction; per step the
  !> shift is A (c0 dt / h) h^2 grad C / 10.
  subroutine shifting_velocity(prm, st, s, wk, axi)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(in) :: st
    type(sorted_t), intent(inout) :: s
    type(csf_work_t), intent(in) :: wk
    logical, intent(in) :: axi
    integer :: n, k
    real(rp) :: d, gx, gz, gn, nn, nx, nz, colour
    real(rp), parameter :: SHIFT_WHOLE = 0.97_rp
    n = s%n
    if (allocated(s%shift)) then
      if (size(s%shift, 2) < n) deallocate(s%shift)
    end if
    if (.not. allocated(s%shift)) allocate(s%shift(2, n + n / 4 + 16))
    d = prm%numerics%shifting * prm%numerics%h * 0.1_rp * prm%eos%c0 * merge(0.5_rp, 1.0_rp, axi)
    !$omp parallel do schedule(static) private(gx, gz, gn, nn, nx, nz, colour)
    do k = 1, n
      if (.not. s%fluid(k) .or. s%grid%order(k) > st%n) then
        s%shift(1:2, k) = 0.0_rp
        cycle
      end if
      gx = wk%ng(NG_GX, k)
      gz = wk%ng(NG_GZ, k)
      ! a kernel cut by the surface: no part along the colour's gradient (c2: axisymmetric only)
      if (axi) then
        colour = wk%c2(k)
      else
        colour = wk%c(k)
      end if
      if (colour < SHIFT_WHOLE) then
        nn = hypot(wk%ng(NG_NX, k), wk%ng(NG_NZ, k))
        if (nn > 0.0_rp) then
          nx = wk%ng(NG_NX, k) / nn
          nz = wk%ng(NG_NZ, k) / nn
          gn = gx * nx + gz * nz
          gx = gx - gn * nx
          gz = gz - gn * nz
        end if
      end if
      if (axi .and. abs(s%x(k)) < 0.5_rp * prm%numerics%h) gx = 0.0_rp
      s%shift(1, k) = -d * gx
      s%shift(2, k) = -d * gz
    end do
    !$omp end parallel do
  end subroutine shifting_velocity

  !> The colour, normal and curvature of the real slots into the particle-order fields of st
  !> (when it has them).
  subroutine fields_to_particles(st, s, wk, kappa)
    type(state_t), intent(inout) :: st
    type(sorted_t), intent(in) :: s
    type(csf_work_t), intent(in) :: wk
    real(rp), intent(in) :: kappa(:)
    integer :: i, k, n
    n = s%n
    if (associated(st%colour) .and. associated(st%st_nx) .and. associated(st%st_nz) &
        .and. associated(st%kappa)) then
      !$omp parallel do schedule(static)
      do i = 1, st%n
        st%colour(i) = 0.0_rp
        st%st_nx(i) = 0.0_rp
        st%st_nz(i) = 0.0_rp
        st%kappa(i) = 0.0_rp
      end do
      !$omp end parallel do
      !$omp parallel do schedule(static) private(i)
      do k = 1, n
        i = s%grid%order(k)
        if (i > st%n) cycle   ! an image slot
        st%colour(i) = wk%c(k)
        st%st_nx(i) = wk%ng(NG_NX, k)
        st%st_nz(i) = wk%ng(NG_NZ, k)
        st%kappa(i) = kappa(k)
      end do
      !$omp end parallel do
    end if

  end subroutine fields_to_particles

  subroutine csf_particle_loops(self, which)
    class(csf_loops_t), intent(inout) :: self
    integer, intent(in) :: which
    integer :: k, n
    real(rp) :: kap, ax, az, wt, kin, kaz, depth, nrx, xr, c0
    logical :: fitted, sparse
    n = self%s%n
    associate (prm => self%prm, kern => self%kern, s => self%s, wk => self%wk, &
               kappa => self%kappa, w0 => self%w0, eps => self%eps, axi => self%axi, &
               colour_delta => self%colour_delta)
      select case (which)
      case (SELF_TERMS)
        !$omp do schedule(static)
        do k = 1, n
          wk%v(k) = s%m(k) / s%rho(k)
          wk%c(k) = merge(wk%v(k) * w0, 0.0_rp, s%fluid(k))
          wk%ng(1:N_NG, k) = 0.0_rp
          if (axi) then
            wk%c2(k) = merge(wk%vmu(k) * w0, 0.0_rp, s%fluid(k))
            wk%n2x(k) = 0.0_rp
            wk%n2z(k) = 0.0_rp
          end if
        end do
        !$omp end do
      case (UNIT_NORMAL)
        !$omp do schedule(static)
        do k = 1, n
          if (s%fluid(k) .and. axi) then   ! filtered by n2, directed by n
            call csf_unit_normal(wk%n2x(k), wk%n2z(k), eps, wk%nhx(k), wk%nhz(k), wk%flag(k))
            if (wk%flag(k) > 0.0_rp) &
              call csf_unit_normal(wk%ng(NG_NX, k), wk%ng(NG_NZ, k), 0.0_rp, wk%nhx(k), wk%nhz(k), wt)
          else if (s%fluid(k)) then
            call csf_unit_normal(wk%ng(NG_NX, k), wk%ng(NG_NZ, k), eps, wk%nhx(k), wk%nhz(k), wk%flag(k))
          else
            wk%nhx(k) = 0.0_rp; wk%nhz(k) = 0.0_rp; wk%flag(k) = 0.0_rp
          end if
          wk%num(k) = 0.0_rp
          wk%den(k) = wk%flag(k) * wk%v(k) * w0   ! self term of the denominator of eq 23
          wk%tden(k) = 0.0_rp                       ! no self term: (r_a - r_a) = 0
        end do
        !$omp end do
      case default   ! FORCE
        !$omp do schedule(static)
        do k = 1, n
          ! no valid normal (flag 0, most particles): every curvature below is 0 and the
          ! force an exact zero, which changes no sum (they start at +0 and never hold -0)
          if (wk%flag(k) == 0.0_rp) then
            kappa(k) = 0.0_rp
            cycle
          end if
          sparse = .false.
          if (axi) then   ! both principal curvatures (physics/axisymmetric.f90)
            if (colour_delta) then
              kin = csf_curvature(wk%num(k), wk%den(k), wk%flag(k))
              kap = kin + wk%flag(k) * azimuthal_curvature(wk%nhx(k), s%x(k), kin, prm%numerics%h)
            else   ! each moved from the particle's row to the surface by k / (1 - k delta)
              kin = csf_surface_curvature(wk%num(k), wk%tden(k), wk%flag(k), 0.0_rp)
              nrx = wk%nhx(k)
              xr = s%x(k)
              depth = csf_depth(wk%c(k), depth_cache(:, kern%kind), prm%numerics%h)
              if (allocated(wk%fit)) then   ! the fitted curve's curvature, normal and point
                call csf_fit_curvature(wk%fit(:, k), wk%nhx(k), wk%nhz(k), sqrt(wk%v(k)), &
                                       prm%surface_tension%fit_points_min, kin, nrx, c0, fitted, sparse)
                if (fitted) then   ! the outer row's point nearest to k, at its own depth
                  xr = max(0.0_rp, s%x(k) + c0 * wk%nhx(k))
                  depth = max(0.0_rp, depth + c0)
                end if
              end if
              kaz = wk%flag(k) * azimuthal_curvature(nrx, xr, kin, prm%numerics%h)
              kap = depth_moved(kin, depth) + depth_moved(kaz, depth)
            end if
          else if (colour_delta) then   ! eq 23 as printed
            kap = csf_curvature(wk%num(k), wk%den(k), wk%flag(k))
          else                     ! free-surface curvature (physics/surface_tension.f90)
            depth = csf_depth(wk%c(k), depth_cache(:, kern%kind), prm%numerics%h)
            kap = csf_surface_curvature(wk%num(k), wk%tden(k), wk%flag(k), depth)
            if (allocated(wk%fit)) then   ! the fitted curve's, moved to the surface
              kin = kap
              call csf_fit_curvature(wk%fit(:, k), wk%nhx(k), wk%nhz(k), sqrt(wk%v(k)), &
                                     prm%surface_tension%fit_points_min, kin, nrx, c0, fitted, sparse)
              if (fitted) kap = depth_moved(kin, max(0.0_rp, depth + c0))
            end if
          end if
          kappa(k) = kap
          if (allocated(wk%kown)) then   ! the rings pair: force after surface_mean_pairs
            wk%kown(k) = kap
            wk%wt(k) = merge(0.0_rp, csf_surface_weight(wk%n2x(k), wk%n2z(k), prm%numerics%h), sparse)
            cycle
          end if
          if (s%fluid(k) .and. prm%surface_tension%sigma > 0.0_rp) then
            if (colour_delta) then
              call csf_acceleration(prm%surface_tension%sigma, s%rho(k), kap, wk%ng(NG_NX, k), &
                                    wk%ng(NG_NZ, k), ax, az)
            else
              ! the planar delta is 2 sum_b V_b grad_a W_ab; the axisymmetric one is complete
              if (axi) then
                wt = csf_surface_weight(wk%n2x(k), wk%n2z(k), prm%numerics%h)
              else
                wt = 2.0_rp * csf_surface_weight(wk%ng(NG_NX, k), wk%ng(NG_NZ, k), prm%numerics%h)
              end if
              call csf_acceleration(prm%surface_tension%sigma, s%rho(k), kap, wt * wk%ng(NG_GX, k), &
                                  wt * wk%ng(NG_GZ, k), ax, az)
            end if
            s%rate(R_AX, k) = s%rate(R_AX, k) + ax
            s%rate(R_AZ, k) = s%rate(R_AZ, k) + az
          end if
        end do
        !$omp end do
      end select
    end associate
  end subroutine csf_particle_loops

  !> One sweep over the fluid-fluid pairs closer than 2h (the common traversal): over the
  !> kept pairs of the last SWEEP_KEEP with PAIRS_ANY_FLUID when kept (the rates sweep's, or
  !> the colour pass's), else finding them and keeping them for the later passes. The
  !> bodies skip the pairs with a boundary particle (pl%mixed; the lists hold no
  !> boundary-boundary pair), so that they see the fluid pairs in the same order either way.
  subroutine sweep(pass, kern, s, wk, kept, axi)
    integer, intent(in) :: pass
    type(kernel_t), intent(in) :: kern
    type(sorted_t), intent(inout) :: s
    type(csf_work_t), intent(inout), target :: wk
    logical, intent(in) :: kept, axi
    type(csf_body_t) :: body
    real(rp) :: red
    body%pass = pass
    body%axi = axi
    body%wk => wk
    red = 0.0_rp
    call pair_sweep(s, kern, PAIRS_ANY_FLUID, body, red, merge(SWEEP_REUSE, SWEEP_KEEP, kept))
  end subroutine sweep

  !> The pairs of one row task for one CSF pass.
  subroutine csf_visit(self, pl, red)
    class(csf_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    associate (wk => self%wk)
      select case (self%pass)
      case (PASS_COLOUR)
        if (self%axi) then   ! also the mode's colour
          call colour_pairs(.true., pl%n, pl%a, pl%b, pl%w, pl%mixed, wk%v, wk%vmu, wk%c, wk%c2)
        else   ! v2, c2 not referenced (flag: an array no other argument is)
          call colour_pairs(.false., pl%n, pl%a, pl%b, pl%w, pl%mixed, wk%v, wk%v, wk%c, wk%flag)
        end if
      case (PASS_NORMAL)   ! axisymmetric: also the gradient of the mode's colour
        if (self%axi) then
          call normal_pairs(.true., pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%f, pl%mixed, wk%v, &
                            wk%c, wk%vmu, wk%gi, wk%c2, wk%ng, wk%n2x, wk%n2z)
        else   ! gi, c2, n2x, n2z not referenced (flag: an array no other argument is)
          call normal_pairs(.false., pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%f, pl%mixed, wk%v, &
                            wk%c, wk%v, wk%v, wk%c, wk%ng, wk%flag, wk%flag)
        end if
      case (PASS_CURVATURE)   ! eq 23: numerator and Shepard denominator
        call curvature_pairs(.true., pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%f, pl%w, pl%mixed, &
                             wk%flag, wk%v, wk%nhx, wk%nhz, wk%num, wk%den)
      case (PASS_SURFACE_FIT)   ! the least-squares sums of the surface fit
        call surface_fit_pairs(pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%w, pl%mixed, wk%flag, wk%outer, &
                               wk%v, wk%nhx, wk%nhz, wk%fit)
      case (PASS_BAND_CURVATURE)   ! numerator, tangential denominator over the surface band
        call band_curvature_pairs(pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%f, pl%mixed, wk%flag, &
                                  wk%band, wk%v, wk%nhx, wk%nhz, wk%num, wk%tden)
      case (PASS_SURFACE_MEAN)   ! the rings pair's weighted mean curvature
        call surface_mean_pairs(pl%n, pl%a, pl%b, pl%w, pl%mixed, wk%v, wk%wt, wk%kown, wk%num, &
                                wk%den)
      case default            ! PASS_SURFACE_CURVATURE: numerator, tangential denominator
        call curvature_pairs(.false., pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%f, pl%w, pl%mixed, &
                             wk%flag, wk%v, wk%nhx, wk%nhz, wk%num, wk%tden)
      end select
    end associate
    red = max(red, 0.0_rp)
  end subroutine csf_visit

end module surface_tension_loops
