!> The momentum / continuity / XSPH pair loop (SPHysics ac + celij/self): for every pair
!> within 2h it accumulates
!>   du_a/dt  = - sum_b m_b (p_a/rho_a^2 + p_b/rho_b^2 [+ tensile] [+ Pi_ab]) grad_a W_ab
!>              [+ laminar viscosity] [+ repulsive wall force]      (gravity is added later)
!>   drho_a/dt = sum_b m_b u_ab . grad_a W_ab
!>   XSPH:     sum_b m_b (u_b - u_a) W_ab / rhobar_ab
!> and the running max of (u_ab . r_ab)/(r_ab^2 + eta^2) used by the time-step control.
!> Dynamic boundary particles interact as fluid does (their accelerations are not used);
!> with repulsive walls, boundary particles only push fluid away (plus the wall viscosity).
!> Boundary-boundary pairs are skipped. In the axisymmetric mode the pressure term and the
!> continuity are those of axisymmetric_loops.f90 (the pressure is left out here).
module rates
  use sphjet_kinds, only: rp, ip, KERNEL_CUBIC, KERNEL_GAUSSIAN, KERNEL_WENDLAND, &
                          VISC_ARTIFICIAL, VISC_LAMINAR, BC_REPULSIVE, GEOM_AXISYMMETRIC
  use sphjet_types, only: sph_params_t, state_t
  use sphjet_kernels, only: kernel_t, kernel_eval
  use sorted_state, only: sorted_t, scatter_rates, N_RATE, R_AX, R_AZ, R_AR, R_XU, R_XW
  use list_rebuild, only: gather_sorted
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_ANY_FLUID, SWEEP_KEEP, &
                       SWEEP_FRESH, SWEEP_REUSE
  use viscosity, only: artificial_pi, reconstructed_dq, laminar_factor
  use tensile_correction, only: tensile_r, tensile_term
  use repulsive_wall, only: repulsive_force
  use surface_tension_loops, only: surface_tension_rates
  use axisymmetric_loops, only: axisymmetric_rates
  use density_diffusion_loops, only: density_diffusion_rates
  use velocity_gradient_loops, only: velocity_gradients, N_GV, G_UX, G_UZ, G_WX, G_WZ
  implicit none
  private
  public :: compute_rates, tensile_q, rates_keep_pairs

  !> Pairs per chunk of the two-pass body (rates_visit).
  integer, parameter :: CHUNK = 128
  !> Columns of a chunk: the pair terms T_*, what pair (a, b) adds to a's and b's sums
  !> (pressure, laminar viscosity, continuity, XSPH), and the pair quantities C_* they are
  !> made of.
  integer, parameter :: T_AX = 1, T_AZ = 2, T_BX = 3, T_BZ = 4, T_LAX = 5, T_LAZ = 6, &
                        T_LBX = 7, T_LBZ = 8, T_AR = 9, T_BR = 10, T_AU = 11, T_AW = 12, &
                        T_BU = 13, T_BW = 14, C_DUX = 15, C_DUZ = 16, C_DQ = 17, C_P = 18, &
                        C_IRHO = 19, C_MA = 20, C_MB = 21, C_IR2 = 22, N_COLUMNS = 22

  !> The rates pair loop body: the case's choices (set once per call) and the sorted state.
  type, extends(pair_body_t) :: rates_body_t
    type(sorted_t), pointer :: s => null()
    logical :: repulsive = .false., laminar = .false., artificial = .false., tensile = .false.
    logical :: reconstruct = .false.   !< Pi of the midpoint jump (s%gv holds the gradients)
    real(rp) :: h = 0.0_rp, eta2 = 0.0_rp, alpha = 0.0_rp, inv_wdp = 0.0_rp, beta = 0.0_rp
    real(rp) :: alpha_art = 0.0_rp, nu_lam = 0.0_rp  !< alpha, nu of the variant on, 0 if off
    real(rp) :: c0 = 0.0_rp, h_swl = 0.0_rp, gz = 0.0_rp, wall_viscosity = 0.0_rp
    logical :: axi_pressure = .false.   !< the pressure pair is the axisymmetric loop's
    real(rp), allocatable :: zero(:)    !< P = 0 for axi_pressure
  contains
    procedure :: visit => rates_visit
  end type rates_body_t

contains

  !> q = dp/h at which the tensile correction is normalised (SPHysics' values).
  pure function tensile_q(kernel) result(q)
    integer(ip), intent(in) :: kernel
    real(rp) :: q
    select case (kernel)
    case (KERNEL_GAUSSIAN); q = sqrt(0.5_rp)
    case (KERNEL_WENDLAND); q = 0.5_rp
    case default;           q = 1.0_rp / 1.5_rp
    end select
  end function tensile_q

  !> Whether the rates sweep keeps its pairs for the sweeps that follow at the same positions
  !> (SWEEP_KEEP): the axisymmetric sums, the surface tension passes and the density
  !> diffusion reuse them; with the reconstructed Pi, the rates sweep reuses the pairs of the
  !> velocity gradient sweep before it. Kept pairs are made outside an open team only
  !> (traversal.f90), so pc_step opens none for such a run.
  pure logical function rates_keep_pairs(prm)
    type(sph_params_t), intent(in) :: prm
    rates_keep_pairs = prm%surface_tension%sigma > 0.0_rp .or. &
                       prm%geometry%kind == GEOM_AXISYMMETRIC .or. &
                       prm%numerics%density_diffusion > 0.0_rp .or. &
                       reconstructs(prm)
  end function rates_keep_pairs

  !> Whether Monaghan's Pi is on: the artificial model's, or numerics.artificial_alpha's on top
  !> of the laminar one.
  pure logical function artificial_on(prm)
    type(sph_params_t), intent(in) :: prm
    artificial_on = prm%viscosity%model == VISC_ARTIFICIAL .or. &
                    (prm%viscosity%model == VISC_LAMINAR .and. &
                     prm%viscosity%artificial_alpha > 0.0_rp)
  end function artificial_on

  !> Whether Pi is on and takes the midpoint jump (numerics.artificial_reconstruction).
  pure logical function reconstructs(prm)
    type(sph_params_t), intent(in) :: prm
    reconstructs = prm%viscosity%reconstruct /= 0 .and. artificial_on(prm)
  end function reconstructs

  subroutine compute_rates(prm, kern, st, s, vmax)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout) :: st
    type(sorted_t), intent(inout), target :: s
    real(rp), intent(inout) :: vmax

    type(rates_body_t) :: body
    integer :: n, k, i, sweep
    real(rp) :: wdp, fdummy, zeta
    logical :: st_on

    body%h = prm%numerics%h
    body%eta2 = 0.01_rp * prm%numerics%h * prm%numerics%h
    body%alpha = prm%viscosity%value
    body%repulsive = prm%boundary%model == BC_REPULSIVE
    body%laminar = prm%viscosity%model == VISC_LAMINAR
    body%artificial = artificial_on(prm)
    body%reconstruct = reconstructs(prm)
    body%tensile = prm%numerics%tensile /= 0
    body%alpha_art = merge(prm%viscosity%value, prm%viscosity%artificial_alpha, &
                           prm%viscosity%model == VISC_ARTIFICIAL)
    body%nu_lam = merge(prm%viscosity%value, 0.0_rp, body%laminar)
    body%beta = prm%boundary%coef / 10.0_rp
    body%c0 = prm%eos%c0
    body%h_swl = prm%boundary%h_swl
    body%gz = prm%gravity%gz
    body%wall_viscosity = prm%boundary%viscosity

    call gather_sorted(st, prm%numerics%h, s, prm)
    n = s%n
    body%s => s
    body%axi_pressure = prm%geometry%kind == GEOM_AXISYMMETRIC
    if (body%axi_pressure) then
      allocate(body%zero(n))
      body%zero = 0.0_rp
    end if

    ! tensile R and the wall geometry in sorted order (an axis image's normal is mirrored);
    ! in an open team (omp_team.f90) by one of its threads
    body%inv_wdp = 0.0_rp
    if (body%tensile) then
      call kernel_eval(kern, tensile_q(kern%kind) * prm%numerics%h, wdp, fdummy)
      body%inv_wdp = 1.0_rp / wdp
    end if
    if (body%tensile .or. body%repulsive) then
      !$omp single
      if (body%tensile) s%tr(1:n) = tensile_r(s%p(1:n), s%pr(1:n))
      if (body%repulsive) then
        do k = 1, n
          i = s%src(k)
          if (i <= st%nb) then
            s%wnx(k) = s%usign(k) * st%wall_nx(i); s%wnz(k) = st%wall_nz(i)
            s%wdb(k) = st%wall_dback(i); s%wdf(k) = st%wall_dfwd(i)
          else
            s%wnx(k) = 0.0_rp; s%wnz(k) = 0.0_rp; s%wdb(k) = 0.0_rp; s%wdf(k) = 0.0_rp
          end if
        end do
      end if
      !$omp end single
    end if

    ! the bulk viscosity (numerics.bulk_viscosity): the pressure of the momentum equation is
    ! p + zeta/rho drho/dt = p - zeta div v, zeta = beta rho0 c0 h, with the density rate of
    ! the last evaluation (st%ar, half a step old). A divergence-free flow does not feel it; a
    ! sound wave of wavenumber k is damped at zeta k^2 / (2 rho). After the tensile term's R,
    ! which stays the equation of state's.
    if (prm%numerics%bulk_viscosity > 0.0_rp) then
      zeta = prm%numerics%bulk_viscosity * prm%eos%rho0 * prm%eos%c0 * prm%numerics%h
      !$omp single
      do k = 1, n
        if (s%fluid(k)) s%pr(k) = s%pr(k) + zeta * st%ar(s%src(k)) / s%rho(k)**3
      end do
      !$omp end single
    end if

    ! the pairs are kept for the sweeps that follow at the same positions: the axisymmetric
    ! sums and the surface tension passes (surface_tension_loops.f90)
    st_on = prm%surface_tension%sigma > 0.0_rp
    sweep = merge(SWEEP_KEEP, SWEEP_FRESH, rates_keep_pairs(prm))
    ! the reconstructed Pi needs every slot's velocity gradient first; its sweep keeps the pairs
    if (body%reconstruct) then
      call velocity_gradients(kern, s)
      sweep = SWEEP_REUSE
    end if
    call pair_sweep(s, kern, PAIRS_ANY_FLUID, body, vmax, sweep)

    ! the hoop terms of the axisymmetric mode (continuity, laminar viscosity)
    if (body%axi_pressure) call axisymmetric_rates(prm, kern, s, st%n, kept=.true.)

    if (st_on) call surface_tension_rates(prm, kern, st, s, kept=.true.)

    ! density diffusion, added to the density rates the loops above have set
    if (prm%numerics%density_diffusion > 0.0_rp) call density_diffusion_rates(prm, kern, s)

    ! back to particle order (inactive particles get zero rates)
    call scatter_rates(s, st, prm%numerics%xsph_eps, prm%numerics%shifting > 0.0_rp)
  end subroutine compute_rates

  !> The pairs of one row task in two passes over chunks of CHUNK pairs (the chunk's columns
  !> stay in the first-level cache): every term each pair adds to its two particles (no
  !> scatter, so it vectorises), then their accumulation in traversal order. Repulsive-wall
  !> pairs (one fluid, one wall particle) take the wall force instead.
  subroutine rates_visit(self, pl, red)
    class(rates_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    real(rp) :: t(CHUNK, N_COLUMNS)
    integer :: k0, k1
    do k0 = 1, pl%n, CHUNK
      k1 = min(pl%n, k0 + CHUNK - 1)
      call rates_pair_terms(self, k1 - k0 + 1, pl%a(k0:k1), pl%b(k0:k1), pl%dx(k0:k1), &
                            pl%dz(k0:k1), pl%r2(k0:k1), pl%w(k0:k1), pl%f(k0:k1), t, red)
      call rates_accumulate(self, pl, k0, k1, t)
    end do
  end subroutine rates_visit

  !> Per pair k: the terms it adds to the sums of its particles a and b (columns T_*, each
  !> the very product the sum adds, so that the accumulation only adds), and red = max of
  !> (u_ab . r_ab)/(r^2 + eta^2). One loop per variant, each chosen outside its loop: a
  !> variant that is off (tensile, artificial or laminar viscosity) costs nothing, not even
  !> the loads of its particle fields. (Adding its exact zero to p, as one loop over all
  !> variants did, changes no sum: p enters only products that the sums add, and a sum that
  !> starts at +0 never holds -0, so adding a zero of either sign leaves it as it is.)
  subroutine rates_pair_terms(b_, np, pa, pb, dx, dz, r2, w, f, t, red)
    type(rates_body_t), intent(in) :: b_
    integer, intent(in) :: np, pa(np), pb(np)
    real(rp), intent(in) :: dx(np), dz(np), r2(np), w(np), f(np)
    real(rp), intent(inout) :: t(CHUNK, N_COLUMNS)
    real(rp), intent(inout) :: red
    associate (s => b_%s)
      if (b_%axi_pressure) then   ! the pressure is axisymmetric_loops.f90's
        call pair_velocity_pressure(np, pa, pb, dx, dz, r2, s%u, s%w, b_%zero, s%rho, s%m, &
                                    b_%eta2, t, red)
      else
        call pair_velocity_pressure(np, pa, pb, dx, dz, r2, s%u, s%w, s%pr, s%rho, s%m, &
                                    b_%eta2, t, red)
      end if
      if (b_%tensile) call pair_tensile(np, pa, pb, w, s%tr, b_%inv_wdp, t)
      ! the reconstruction replaces the approach rate that Pi takes (the time-step control
      ! has had the particles' own in red)
      if (b_%reconstruct) call pair_midpoint_dq(np, pa, pb, dx, dz, s%gv, t)
      if (b_%artificial) call pair_artificial(np, pa, pb, s%c, b_%alpha_art, b_%h, t)
      call pair_sum_terms(np, dx, dz, w, f, t)
      if (b_%laminar) call pair_laminar(np, r2, f, b_%nu_lam, t)
    end associate
  end subroutine rates_pair_terms

  !> u_ab, the approach rate (u_ab . r_ab)/(r^2 + eta^2), p_a/rho_a^2 + p_b/rho_b^2,
  !> 1/(rho_a + rho_b), 1/(r^2 + eta^2), m_a, m_b; red. The pair's only two divisions: the
  !> viscosities and XSPH multiply by these reciprocals.
  pure subroutine pair_velocity_pressure(np, pa, pb, dx, dz, r2, u, vw, pr, rho, m, eta2, t, red)
    integer, intent(in) :: np, pa(np), pb(np)
    real(rp), intent(in) :: dx(np), dz(np), r2(np), u(*), vw(*), pr(*), rho(*), m(*), eta2
    real(rp), intent(inout) :: t(CHUNK, N_COLUMNS), red
    integer :: k, a, b
    real(rp) :: dux, duz, dq, ir2
    !$omp simd private(a, b, dux, duz, dq, ir2) reduction(max:red)
    do k = 1, np
      a = pa(k)
      b = pb(k)
      dux = u(a) - u(b)
      duz = vw(a) - vw(b)
      ir2 = 1.0_rp / (r2(k) + eta2)
      dq = (dx(k) * dux + dz(k) * duz) * ir2
      red = max(red, dq)
      t(k, C_DUX) = dux
      t(k, C_DUZ) = duz
      t(k, C_DQ) = dq
      t(k, C_IR2) = ir2
      t(k, C_P) = pr(a) + pr(b)
      t(k, C_IRHO) = 1.0_rp / (rho(a) + rho(b))
      t(k, C_MA) = m(a)
      t(k, C_MB) = m(b)
    end do
  end subroutine pair_velocity_pressure

  !> p += the tensile correction.
  pure subroutine pair_tensile(np, pa, pb, w, tr, inv_wdp, t)
    integer, intent(in) :: np, pa(np), pb(np)
    real(rp), intent(in) :: w(np), tr(*), inv_wdp
    real(rp), intent(inout) :: t(CHUNK, N_COLUMNS)
    integer :: k
    do k = 1, np
      t(k, C_P) = t(k, C_P) + tensile_term(tr(pa(k)), tr(pb(k)), w(k), inv_wdp)
    end do
  end subroutine pair_tensile

  !> p += Pi_ab, the artificial viscosity.
  pure subroutine pair_artificial(np, pa, pb, c, alpha, h, t)
    integer, intent(in) :: np, pa(np), pb(np)
    real(rp), intent(in) :: c(*), alpha, h
    real(rp), intent(inout) :: t(CHUNK, N_COLUMNS)
    integer :: k
    do k = 1, np
      t(k, C_P) = t(k, C_P) + artificial_pi(alpha, h, 0.5_rp * (c(pa(k)) + c(pb(k))), &
                                            2.0_rp * t(k, C_IRHO), t(k, C_DQ))
    end do
  end subroutine pair_artificial

  !> The approach rate of Pi at the pair's midpoint (reconstructed_dq) in place of the
  !> particles' own, with the slots' velocity gradients gv(G_*, k) (velocity_gradient_loops.f90).
  pure subroutine pair_midpoint_dq(np, pa, pb, dx, dz, gv, t)
    integer, intent(in) :: np, pa(np), pb(np)
    real(rp), intent(in) :: dx(np), dz(np), gv(N_GV, *)
    real(rp), intent(inout) :: t(CHUNK, N_COLUMNS)
    integer :: k, a, b
    real(rp) :: ea, eb
    do k = 1, np
      a = pa(k)
      b = pb(k)
      ea = (dx(k) * (gv(G_UX, a) * dx(k) + gv(G_UZ, a) * dz(k)) + &
            dz(k) * (gv(G_WX, a) * dx(k) + gv(G_WZ, a) * dz(k))) * t(k, C_IR2)
      eb = (dx(k) * (gv(G_UX, b) * dx(k) + gv(G_UZ, b) * dz(k)) + &
            dz(k) * (gv(G_WX, b) * dx(k) + gv(G_WZ, b) * dz(k))) * t(k, C_IR2)
      t(k, C_DQ) = reconstructed_dq(t(k, C_DQ), ea, eb)
    end do
  end subroutine pair_midpoint_dq

  !> The pressure, continuity and XSPH terms.
  pure subroutine pair_sum_terms(np, dx, dz, w, f, t)
    integer, intent(in) :: np
    real(rp), intent(in) :: dx(np), dz(np), w(np), f(np)
    real(rp), intent(inout) :: t(CHUNK, N_COLUMNS)
    integer :: k
    real(rp) :: gx, gz, dv, xs
    do k = 1, np
      associate (ma => t(k, C_MA), mb => t(k, C_MB), p => t(k, C_P), dux => t(k, C_DUX), &
                 duz => t(k, C_DUZ))
        gx = f(k) * dx(k)
        gz = f(k) * dz(k)
        t(k, T_AX) = mb * p * gx
        t(k, T_AZ) = mb * p * gz
        t(k, T_BX) = ma * p * gx
        t(k, T_BZ) = ma * p * gz
        dv = dux * gx + duz * gz
        t(k, T_AR) = mb * dv
        t(k, T_BR) = ma * dv
        xs = 2.0_rp * w(k) * t(k, C_IRHO)
        t(k, T_AU) = mb * dux * xs
        t(k, T_AW) = mb * duz * xs
        t(k, T_BU) = ma * dux * xs
        t(k, T_BW) = ma * duz * xs
      end associate
    end do
  end subroutine pair_sum_terms

  !> The laminar viscosity terms.
  pure subroutine pair_laminar(np, r2, f, nu, t)
    integer, intent(in) :: np
    real(rp), intent(in) :: r2(np), f(np), nu
    real(rp), intent(inout) :: t(CHUNK, N_COLUMNS)
    integer :: k
    real(rp) :: lam
    do k = 1, np
      lam = laminar_factor(nu, t(k, C_IRHO), f(k), r2(k), t(k, C_IR2))
      t(k, T_LAX) = t(k, C_MB) * lam * t(k, C_DUX)
      t(k, T_LAZ) = t(k, C_MB) * lam * t(k, C_DUZ)
      t(k, T_LBX) = t(k, C_MA) * lam * t(k, C_DUX)
      t(k, T_LBZ) = t(k, C_MA) * lam * t(k, C_DUZ)
    end do
  end subroutine pair_laminar

  !> Accumulates the terms of pairs k0..k1 into the sorted rates, pair by pair in traversal
  !> order.
  subroutine rates_accumulate(b_, pl, k0, k1, t)
    type(rates_body_t), intent(in) :: b_
    type(pair_list_t), intent(in) :: pl
    integer, intent(in) :: k0, k1
    real(rp), intent(in) :: t(CHUNK, N_COLUMNS)
    type(sorted_t), pointer :: s
    integer :: k, j0, j, nw
    integer :: kw(CHUNK)
    s => b_%s
    ! runs of fluid pairs (all pairs but the repulsive-wall ones) go to the plain sum
    j0 = k0
    if (b_%repulsive) then
      ! the wall pairs' places first, without a branch per pair (a loop that tested each
      ! pair and called out of it kept its counters in memory: 6% of ObstW's time)
      nw = 0
      do k = k0, k1
        kw(nw + 1) = k
        nw = nw + merge(1, 0, pl%mixed(k))
      end do
      do j = 1, nw
        k = kw(j)
        call accumulate_fluid(j0, k - 1, k0 - 1, b_%laminar, pl%a, pl%b, t, s%rate)
        call accumulate_wall(b_, s, pl%a(k), pl%b(k), pl%dx(k), pl%dz(k), pl%r2(k), pl%f(k))
        j0 = k + 1
      end do
    end if
    call accumulate_fluid(j0, k1, k0 - 1, b_%laminar, pl%a, pl%b, t, s%rate)
  end subroutine rates_accumulate

  !> Pressure (+ viscosity), continuity and XSPH sums of pairs j0..j1 (term row k - off) into
  !> the sorted rates r(R_*, slot). The pairs of one particle a follow each other (list order:
  !> cell, a, partner cell, b), and no pair of such a run has a as its b: a's sums are carried
  !> in registers along the run, with the same additions in the same order as one pair at a
  !> time.
  pure subroutine accumulate_fluid(j0, j1, off, laminar, pa, pb, t, r)
    integer, intent(in) :: j0, j1, off, pa(*), pb(*)
    logical, intent(in) :: laminar
    real(rp), intent(in) :: t(CHUNK, N_COLUMNS)
    real(rp), intent(inout) :: r(N_RATE, *)
    integer :: k, a, b, i
    real(rp) :: sa(N_RATE)
    k = j0
    do while (k <= j1)
      a = pa(k)
      sa = r(:, a)
      do while (k <= j1)
        if (pa(k) /= a) exit
        b = pb(k)
        i = k - off
        sa(R_AX) = sa(R_AX) - t(i, T_AX)
        sa(R_AZ) = sa(R_AZ) - t(i, T_AZ)
        r(R_AX, b) = r(R_AX, b) + t(i, T_BX)
        r(R_AZ, b) = r(R_AZ, b) + t(i, T_BZ)
        if (laminar) then
          sa(R_AX) = sa(R_AX) + t(i, T_LAX)
          sa(R_AZ) = sa(R_AZ) + t(i, T_LAZ)
          r(R_AX, b) = r(R_AX, b) - t(i, T_LBX)
          r(R_AZ, b) = r(R_AZ, b) - t(i, T_LBZ)
        end if
        sa(R_AR) = sa(R_AR) + t(i, T_AR)
        r(R_AR, b) = r(R_AR, b) + t(i, T_BR)
        sa(R_XU) = sa(R_XU) - t(i, T_AU)
        sa(R_XW) = sa(R_XW) - t(i, T_AW)
        r(R_XU, b) = r(R_XU, b) + t(i, T_BU)
        r(R_XW, b) = r(R_XW, b) + t(i, T_BW)
        k = k + 1
      end do
      r(:, a) = sa
    end do
  end subroutine accumulate_fluid

  !> A repulsive-wall pair: the fluid particle of (a, b) pushed by the wall particle.
  subroutine accumulate_wall(b_, s, a, b, dx, dz, r2, f)
    type(rates_body_t), intent(in) :: b_
    type(sorted_t), intent(inout) :: s
    integer, intent(in) :: a, b
    real(rp), intent(in) :: dx, dz, r2, f
    integer :: fl, wl
    real(rp) :: sgn, fx, fz, vw, dux, duz
    dux = s%u(a) - s%u(b)
    duz = s%w(a) - s%w(b)
    if (s%fluid(a)) then
      fl = a; wl = b; sgn = 1.0_rp
    else
      fl = b; wl = a; sgn = -1.0_rp
    end if
    call repulsive_force(sgn * dx, sgn * dz, sgn * dux, sgn * duz, &
                         s%wnx(wl), s%wnz(wl), s%wdb(wl), s%wdf(wl), s%c(fl), b_%c0, &
                         s%z(fl), s%z(wl), s%u(wl), s%w(wl), b_%h, b_%h_swl, b_%gz, &
                         b_%beta, fx, fz)
    vw = s%m(fl) / s%rho(fl) * b_%wall_viscosity * (f * r2) / (r2 + b_%eta2)
    s%rate(R_AX, fl) = s%rate(R_AX, fl) + fx + vw * sgn * dux
    s%rate(R_AZ, fl) = s%rate(R_AZ, fl) + fz + vw * sgn * duz
  end subroutine accumulate_wall

end module rates
