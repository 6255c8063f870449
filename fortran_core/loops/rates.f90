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
  use sorted_state, only: sorted_t, gather_sorted
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_ANY_FLUID
  use viscosity, only: artificial_pi, laminar_factor
  use tensile_correction, only: tensile_r, tensile_term
  use repulsive_wall, only: repulsive_force
  use surface_tension_loops, only: surface_tension_rates
  use axisymmetric_loops, only: axisymmetric_rates
  implicit none
  private
  public :: compute_rates, tensile_q

  !> The rates pair loop body: the case's choices (set once per call) and the sorted state.
  type, extends(pair_body_t) :: rates_body_t
    type(sorted_t), pointer :: s => null()
    logical :: repulsive = .false., laminar = .false., artificial = .false., tensile = .false.
    real(rp) :: h = 0.0_rp, eta2 = 0.0_rp, alpha = 0.0_rp, inv_wdp = 0.0_rp, beta = 0.0_rp
    real(rp) :: alpha_art = 0.0_rp, nu_lam = 0.0_rp  !< alpha, nu of the variant on, 0 if off
    real(rp) :: c0 = 0.0_rp, h_swl = 0.0_rp, gz = 0.0_rp, wall_viscosity = 0.0_rp
    logical :: axi_pressure = .false.   !< the pressure pair is the axisymmetric loop's
    real(rp), allocatable :: zero(:)                            !< P = 0 for axi_pressure
    real(rp), allocatable :: tr(:)                              !< tensile R per particle
    real(rp), allocatable :: wnx(:), wnz(:), wdb(:), wdf(:)     !< repulsive wall geometry
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

  subroutine compute_rates(prm, kern, st, s, vmax)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout) :: st
    type(sorted_t), intent(inout), target :: s
    real(rp), intent(inout) :: vmax

    type(rates_body_t) :: body
    integer :: n, k, i
    real(rp) :: wdp, fdummy

    body%h = prm%h
    body%eta2 = 0.01_rp * prm%h * prm%h
    body%alpha = prm%visc_value
    body%repulsive = prm%boundary == BC_REPULSIVE
    body%laminar = prm%viscosity == VISC_LAMINAR
    body%artificial = prm%viscosity == VISC_ARTIFICIAL
    body%tensile = prm%tensile /= 0
    body%alpha_art = merge(prm%visc_value, 0.0_rp, body%artificial)
    body%nu_lam = merge(prm%visc_value, 0.0_rp, body%laminar)
    body%beta = prm%coef / 10.0_rp
    body%c0 = prm%c0
    body%h_swl = prm%h_swl
    body%gz = prm%gz
    body%wall_viscosity = prm%wall_viscosity

    call gather_sorted(st, prm%h, s, prm)
    n = s%n
    body%s => s
    body%axi_pressure = prm%geometry == GEOM_AXISYMMETRIC
    if (body%axi_pressure) then
      allocate(body%zero(n))
      body%zero = 0.0_rp
    end if

    if (body%tensile) then
      call kernel_eval(kern, tensile_q(kern%kind) * prm%h, wdp, fdummy)
      body%inv_wdp = 1.0_rp / wdp
      allocate(body%tr(n))
      body%tr = tensile_r(s%p(1:n), s%pr(1:n))
    else
      body%inv_wdp = 0.0_rp
      allocate(body%tr(n))
      body%tr = 0.0_rp
    end if
    if (body%repulsive) then
      allocate(body%wnx(n), body%wnz(n), body%wdb(n), body%wdf(n))
      do k = 1, n
        i = s%src(k)
        if (i <= st%nb) then   ! an axis image's normal is mirrored (usign = -1)
          body%wnx(k) = s%usign(k) * st%wall_nx(i); body%wnz(k) = st%wall_nz(i)
          body%wdb(k) = st%wall_dback(i); body%wdf(k) = st%wall_dfwd(i)
        else
          body%wnx(k) = 0.0_rp; body%wnz(k) = 0.0_rp; body%wdb(k) = 0.0_rp; body%wdf(k) = 0.0_rp
        end if
      end do
    end if

    call pair_sweep(s, kern, PAIRS_ANY_FLUID, body, vmax)

    ! the hoop terms of the axisymmetric mode (continuity, laminar viscosity)
    if (prm%geometry == GEOM_AXISYMMETRIC) call axisymmetric_rates(prm, kern, s, st%n)

    if (prm%sigma > 0.0_rp) call surface_tension_rates(prm, kern, st, s)

    ! Scatter back to particle order; inactive particles get zero rates. The sorted slots are
    ! exactly the active particles, so the two loops write disjoint entries and need no
    ! barrier between them (nowait): one barrier per scatter, not two. Image slots
    ! (order > st%n) are not scattered: their sums are discarded.
    !$omp parallel private(i)
    !$omp do schedule(static)
    do k = 1, n
      i = s%grid%order(k)
      if (i > st%n) cycle
      st%ax(i) = s%ax(k)
      st%az(i) = s%az(k)
      st%ar(i) = s%ar(k)
      st%xsph_u(i) = prm%xsph_eps * s%xu(k)
      st%xsph_w(i) = prm%xsph_eps * s%xw(k)
    end do
    !$omp end do nowait
    !$omp do schedule(static)
    do i = 1, st%n
      if (st%active(i) /= 0) cycle
      st%ax(i) = 0.0_rp
      st%az(i) = 0.0_rp
      st%ar(i) = 0.0_rp
      st%xsph_u(i) = 0.0_rp
      st%xsph_w(i) = 0.0_rp
    end do
    !$omp end do
    !$omp end parallel
  end subroutine compute_rates

  !> The pairs of one row task in two passes: the pair terms of every pair (no scatter, the
  !> variant flags invariant in the loop, so it vectorises), then their accumulation in
  !> traversal order. Repulsive-wall pairs (one fluid, one wall particle) take the wall
  !> force instead.
  subroutine rates_visit(self, pl, red)
    class(rates_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    if (self%axi_pressure) then
      call rates_pair_terms(self, pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%r2, pl%w, pl%f, &
                            self%s%u, self%s%w, self%zero, self%s%c, self%s%rho, self%tr, &
                            pl%t(:, 1), pl%t(:, 2), pl%t(:, 3), pl%t(:, 4), red)
    else
      call rates_pair_terms(self, pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%r2, pl%w, pl%f, &
                            self%s%u, self%s%w, self%s%pr, self%s%c, self%s%rho, self%tr, &
                            pl%t(:, 1), pl%t(:, 2), pl%t(:, 3), pl%t(:, 4), red)
    end if
    call rates_accumulate(self, pl, pl%t(:, 1), pl%t(:, 2), pl%t(:, 3), pl%t(:, 4))
  end subroutine rates_visit

  !> Per pair: pv (pressure + tensile + artificial viscosity), u_ab and the laminar factor;
  !> red = max of (u_ab . r_ab)/(r^2 + eta^2).
  subroutine rates_pair_terms(b_, np, pa, pb, dx, dz, r2, w, f, u, vw, pr, c, rho, tr, &
                              pv, dux, duz, lam, red)
    type(rates_body_t), intent(in) :: b_
    integer, intent(in) :: np, pa(:), pb(:)
    real(rp), intent(in) :: dx(:), dz(:), r2(:), w(:), f(:), u(:), vw(:), pr(:), c(:), &
                            rho(:), tr(:)
    real(rp), intent(out) :: pv(:), dux(:), duz(:), lam(:)
    real(rp), intent(inout) :: red
    integer :: k, a, b
    real(rp) :: dot, p
    !$omp simd private(a, b, dot, p) reduction(max:red)
    do k = 1, np
      a = pa(k)
      b = pb(k)
      dux(k) = u(a) - u(b)
      duz(k) = vw(a) - vw(b)
      dot = dx(k) * dux(k) + dz(k) * duz(k)
      red = max(red, dot / (r2(k) + b_%eta2))
      ! Variants off contribute an exact zero (tr = 0, alpha = 0 or nu = 0): no branch here.
      p = pr(a) + pr(b)
      p = p + tensile_term(tr(a), tr(b), w(k), b_%inv_wdp)
      p = p + artificial_pi(b_%alpha_art, b_%h, 0.5_rp * (c(a) + c(b)), &
                            0.5_rp * (rho(a) + rho(b)), dot, r2(k), b_%eta2)
      pv(k) = p
      lam(k) = laminar_factor(b_%nu_lam, rho(a), rho(b), f(k), r2(k), b_%eta2)
    end do
  end subroutine rates_pair_terms

  !> Accumulates the pair terms into the sorted rates, pair by pair in traversal order.
  subroutine rates_accumulate(b_, pl, pv, dux, duz, lam)
    type(rates_body_t), intent(in) :: b_
    type(pair_list_t), intent(in) :: pl
    real(rp), intent(in) :: pv(:), dux(:), duz(:), lam(:)
    type(sorted_t), pointer :: s
    integer :: k, k0
    s => b_%s
    ! runs of fluid pairs (all pairs but the repulsive-wall ones) go to the plain sum
    k0 = 1
    do k = 1, pl%n
      if (.not. (b_%repulsive .and. pl%mixed(k))) cycle
      call accumulate_fluid(k0, k - 1, b_%laminar, pl%a, pl%b, pl%dx, pl%dz, pl%w, pl%f, &
                            pv, dux, duz, lam, s%m, s%rho, s%ax, s%az, s%ar, s%xu, s%xw)
      call accumulate_wall(b_, s, pl%a(k), pl%b(k), pl%dx(k), pl%dz(k), pl%r2(k), pl%f(k), &
                           dux(k), duz(k))
      k0 = k + 1
    end do
    call accumulate_fluid(k0, pl%n, b_%laminar, pl%a, pl%b, pl%dx, pl%dz, pl%w, pl%f, &
                          pv, dux, duz, lam, s%m, s%rho, s%ax, s%az, s%ar, s%xu, s%xw)
  end subroutine rates_accumulate

  !> Pressure (+ viscosity), continuity and XSPH sums of pairs k0..k1.
  pure subroutine accumulate_fluid(k0, k1, laminar, pa, pb, dx, dz, w, f, pv, dux, duz, lam, &
                                   m, rho, ax, az, ar, xu, xw)
    integer, intent(in) :: k0, k1, pa(:), pb(:)
    logical, intent(in) :: laminar
    real(rp), intent(in) :: dx(:), dz(:), w(:), f(:), pv(:), dux(:), duz(:), lam(:), m(:), rho(:)
    real(rp), intent(inout) :: ax(:), az(:), ar(:), xu(:), xw(:)
    integer :: k, a, b
    real(rp) :: gx, gz, dv, t
    do k = k0, k1
      a = pa(k)
      b = pb(k)
      gx = f(k) * dx(k)
      gz = f(k) * dz(k)
      ax(a) = ax(a) - m(b) * pv(k) * gx
      az(a) = az(a) - m(b) * pv(k) * gz
      ax(b) = ax(b) + m(a) * pv(k) * gx
      az(b) = az(b) + m(a) * pv(k) * gz
      if (laminar) then
        ax(a) = ax(a) + m(b) * lam(k) * dux(k)
        az(a) = az(a) + m(b) * lam(k) * duz(k)
        ax(b) = ax(b) - m(a) * lam(k) * dux(k)
        az(b) = az(b) - m(a) * lam(k) * duz(k)
      end if
      dv = dux(k) * gx + duz(k) * gz
      ar(a) = ar(a) + m(b) * dv
      ar(b) = ar(b) + m(a) * dv
      t = 2.0_rp * w(k) / (rho(a) + rho(b))
      xu(a) = xu(a) - m(b) * dux(k) * t
      xw(a) = xw(a) - m(b) * duz(k) * t
      xu(b) = xu(b) + m(a) * dux(k) * t
      xw(b) = xw(b) + m(a) * duz(k) * t
    end do
  end subroutine accumulate_fluid

  !> A repulsive-wall pair: the fluid particle of (a, b) pushed by the wall particle.
  subroutine accumulate_wall(b_, s, a, b, dx, dz, r2, f, dux, duz)
    type(rates_body_t), intent(in) :: b_
    type(sorted_t), intent(inout) :: s
    integer, intent(in) :: a, b
    real(rp), intent(in) :: dx, dz, r2, f, dux, duz
    integer :: fl, wl
    real(rp) :: sgn, fx, fz, vw
    if (s%fluid(a)) then
      fl = a; wl = b; sgn = 1.0_rp
    else
      fl = b; wl = a; sgn = -1.0_rp
    end if
    call repulsive_force(sgn * dx, sgn * dz, sgn * dux, sgn * duz, &
                         b_%wnx(wl), b_%wnz(wl), b_%wdb(wl), b_%wdf(wl), s%c(fl), b_%c0, &
                         s%z(fl), s%z(wl), s%u(wl), s%w(wl), b_%h, b_%h_swl, b_%gz, &
                         b_%beta, fx, fz)
    vw = s%m(fl) / s%rho(fl) * b_%wall_viscosity * (f * r2) / (r2 + b_%eta2)
    s%ax(fl) = s%ax(fl) + fx + vw * sgn * dux
    s%az(fl) = s%az(fl) + fz + vw * sgn * duz
  end subroutine accumulate_wall

end module rates
