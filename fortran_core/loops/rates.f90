!> The momentum / continuity / XSPH pair loop (SPHysics ac + celij/self): for every pair
!> within 2h it accumulates
!>   du_a/dt  = - sum_b m_b (p_a/rho_a^2 + p_b/rho_b^2 [+ tensile] [+ Pi_ab]) grad_a W_ab
!>              [+ laminar viscosity] [+ repulsive wall force]      (gravity is added later)
!>   drho_a/dt = sum_b m_b u_ab . grad_a W_ab
!>   XSPH:     sum_b m_b (u_b - u_a) W_ab / rhobar_ab
!> and the running max of (u_ab . r_ab)/(r_ab^2 + eta^2) used by the time-step control.
!> Dynamic boundary particles interact as fluid does (their accelerations are not used);
!> with repulsive walls, boundary particles only push fluid away (plus the wall viscosity).
!> Boundary-boundary pairs are skipped.
module rates
  use sphjet_kinds, only: rp, ip, KERNEL_CUBIC, KERNEL_GAUSSIAN, KERNEL_WENDLAND, &
                          VISC_ARTIFICIAL, VISC_LAMINAR, BC_REPULSIVE
  use sphjet_types, only: sph_params_t, state_t
  use sphjet_kernels, only: kernel_t, kernel_eval
  use sorted_state, only: sorted_t, gather_sorted
  use traversal, only: row_cell_pairs, MAX_PAIRS_PER_CELL
  use viscosity, only: artificial_pi, laminar_factor
  use tensile_correction, only: tensile_r, tensile_term
  use repulsive_wall, only: repulsive_force
  use surface_tension_loops, only: surface_tension_rates
  implicit none
  private
  public :: compute_rates, tensile_q

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
    type(sorted_t), intent(inout) :: s
    real(rp), intent(inout) :: vmax

    real(rp), allocatable :: tr(:), wnx(:), wnz(:), wdb(:), wdf(:)
    integer, allocatable :: list(:, :)
    integer :: n, k, i, phase, row, npair, ip_, a, b, b0, fl, wl
    logical :: repulsive, laminar, artificial, tensile
    real(rp) :: dx, dz, r2, r, wab, f, gx, gz, dux, duz, dot, pv, lam, dv, t, eta2, alpha, &
                inv_wdp, wdp, fdummy, sgn, fx, fz, beta, vw
    real(rp) :: h

    h = prm%h
    eta2 = 0.01_rp * h * h
    alpha = prm%visc_value
    repulsive = prm%boundary == BC_REPULSIVE
    laminar = prm%viscosity == VISC_LAMINAR
    artificial = prm%viscosity == VISC_ARTIFICIAL
    tensile = prm%tensile /= 0
    beta = prm%coef / 10.0_rp

    call gather_sorted(st, h, s)
    n = s%n

    if (tensile) then
      call kernel_eval(kern, tensile_q(kern%kind) * h, wdp, fdummy)
      inv_wdp = 1.0_rp / wdp
      allocate(tr(n))
      tr = tensile_r(s%p(1:n), s%pr(1:n))
    else
      inv_wdp = 0.0_rp
      allocate(tr(1))
    end if
    if (repulsive) then
      allocate(wnx(n), wnz(n), wdb(n), wdf(n))
      do k = 1, n
        i = s%grid%order(k)
        if (i <= st%nb) then
          wnx(k) = st%wall_nx(i); wnz(k) = st%wall_nz(i)
          wdb(k) = st%wall_dback(i); wdf(k) = st%wall_dfwd(i)
        else
          wnx(k) = 0.0_rp; wnz(k) = 0.0_rp; wdb(k) = 0.0_rp; wdf(k) = 0.0_rp
        end if
      end do
    end if

    do phase = 0, 1
      !$omp parallel private(list, npair, ip_, a, b, b0, dx, dz, r2, r, wab, f, gx, gz, dux, &
      !$omp&   duz, dot, pv, lam, dv, t, fl, wl, sgn, fx, fz, vw) reduction(max:vmax)
      allocate(list(5, MAX_PAIRS_PER_CELL * s%grid%ncx))
      !$omp do schedule(dynamic, 1)
      do row = phase, s%grid%ncz - 1, 2
        call row_cell_pairs(s%grid, row, list, npair)
        do ip_ = 1, npair
          do a = list(1, ip_), list(2, ip_)
            b0 = list(3, ip_)
            if (list(5, ip_) == 1) b0 = a + 1
            do b = b0, list(4, ip_)
              if (.not. (s%fluid(a) .or. s%fluid(b))) cycle
              dx = s%x(a) - s%x(b)
              dz = s%z(a) - s%z(b)
              r2 = dx * dx + dz * dz
              if (r2 >= kern%support2 .or. r2 <= 1.0e-18_rp) cycle
              r = sqrt(r2)
              call kernel_eval(kern, r, wab, f)
              gx = f * dx
              gz = f * dz
              dux = s%u(a) - s%u(b)
              duz = s%w(a) - s%w(b)
              dot = dx * dux + dz * duz
              vmax = max(vmax, dot / (r2 + eta2))

              if (repulsive .and. .not. (s%fluid(a) .and. s%fluid(b))) then
                ! fluid particle fl pushed by wall particle wl
                if (s%fluid(a)) then
                  fl = a; wl = b; sgn = 1.0_rp
                else
                  fl = b; wl = a; sgn = -1.0_rp
                end if
                call repulsive_force(sgn * dx, sgn * dz, sgn * dux, sgn * duz, wnx(wl), wnz(wl), &
                                     wdb(wl), wdf(wl), s%c(fl), prm%c0, s%z(fl), s%z(wl), &
                                     s%u(wl), s%w(wl), h, prm%h_swl, prm%gz, beta, fx, fz)
                vw = s%m(fl) / s%rho(fl) * prm%wall_viscosity * (f * r2) / (r2 + eta2)
                s%ax(fl) = s%ax(fl) + fx + vw * sgn * dux
                s%az(fl) = s%az(fl) + fz + vw * sgn * duz
                cycle
              end if

              pv = s%pr(a) + s%pr(b)
              if (tensile) pv = pv + tensile_term(tr(a), tr(b), wab, inv_wdp)
              if (artificial) pv = pv + artificial_pi(alpha, h, 0.5_rp * (s%c(a) + s%c(b)), &
                                                      0.5_rp * (s%rho(a) + s%rho(b)), dot, r2, eta2)
              s%ax(a) = s%ax(a) - s%m(b) * pv * gx
              s%az(a) = s%az(a) - s%m(b) * pv * gz
              s%ax(b) = s%ax(b) + s%m(a) * pv * gx
              s%az(b) = s%az(b) + s%m(a) * pv * gz
              if (laminar) then
                lam = laminar_factor(alpha, s%rho(a), s%rho(b), f, r2, eta2)
                s%ax(a) = s%ax(a) + s%m(b) * lam * dux
                s%az(a) = s%az(a) + s%m(b) * lam * duz
                s%ax(b) = s%ax(b) - s%m(a) * lam * dux
                s%az(b) = s%az(b) - s%m(a) * lam * duz
              end if
              dv = dux * gx + duz * gz
              s%ar(a) = s%ar(a) + s%m(b) * dv
              s%ar(b) = s%ar(b) + s%m(a) * dv
              t = 2.0_rp * wab / (s%rho(a) + s%rho(b))
              s%xu(a) = s%xu(a) - s%m(b) * dux * t
              s%xw(a) = s%xw(a) - s%m(b) * duz * t
              s%xu(b) = s%xu(b) + s%m(a) * dux * t
              s%xw(b) = s%xw(b) + s%m(a) * duz * t
            end do
          end do
        end do
      end do
      !$omp end do
      deallocate(list)
      !$omp end parallel
    end do

    if (prm%sigma > 0.0_rp) call surface_tension_rates(prm, kern, st, s)

    ! Scatter back to particle order; inactive particles get zero rates. The sorted slots are
    ! exactly the active particles, so the two loops write disjoint entries and need no
    ! barrier between them (nowait): one barrier per scatter, not two.
    !$omp parallel private(i)
    !$omp do schedule(static)
    do k = 1, n
      i = s%grid%order(k)
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

end module rates
