!> Density filters over fluid-fluid pairs (boundary particles neither filter nor are used):
!>   Shepard: rho_a = sum_b m_b W_ab / sum_b V_b W_ab
!>   MLS:     rho_a = sum_b m_b W_ab (beta0 + beta1 . (r_a - r_b)), beta = A^{-1} e1
!> sums include the particle itself (W(0)), volumes V_b = m_b/rho_b at the time of the filter.
module filter_loops
  use sphjet_kinds, only: rp, ip, KIND_FLUID, FILTER_SHEPARD, FILTER_MLS
  use sphjet_types, only: sph_params_t, state_t
  use sphjet_kernels, only: kernel_t, kernel_eval, kernel_w0
  use sorted_state, only: sorted_t, gather_sorted
  use traversal, only: row_cell_pairs, MAX_PAIRS_PER_CELL
  use density_filter, only: mls_beta
  use eos_tait, only: tait_pressure, tait_sound_speed
  implicit none
  private
  public :: apply_density_filter

contains

  subroutine apply_density_filter(prm, kern, st, s, n_singular)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout) :: st
    type(sorted_t), intent(inout) :: s
    integer, intent(out) :: n_singular
    real(rp), allocatable :: acc(:, :), beta(:, :), v(:), rnew(:)
    integer, allocatable :: list(:, :)
    integer :: n, k, i, phase, row, npair, ip_, a, b, b0, pass, npass
    real(rp) :: dx, dz, r2, wab, f, w0, wa, wb
    logical :: mls, sing

    n_singular = 0
    if (prm%density_filter /= FILTER_SHEPARD .and. prm%density_filter /= FILTER_MLS) return
    mls = prm%density_filter == FILTER_MLS
    call gather_sorted(st, prm%h, s)
    n = s%n
    w0 = kernel_w0(kern)
    allocate(v(n), rnew(n), beta(3, n))
    v = s%m(1:n) / s%rho(1:n)
    npass = merge(2, 1, mls)
    if (mls) then
      allocate(acc(6, n))
    else
      allocate(acc(2, n))
    end if

    do pass = 1, npass
      acc = 0.0_rp
      rnew = 0.0_rp
      do phase = 0, 1
        !$omp parallel private(list, npair, ip_, a, b, b0, dx, dz, r2, wab, f, wa, wb)
        allocate(list(5, MAX_PAIRS_PER_CELL * s%grid%ncx))
        !$omp do schedule(dynamic, 1)
        do row = phase, s%grid%ncz - 1, 2
          call row_cell_pairs(s%grid, row, list, npair)
          do ip_ = 1, npair
            do a = list(1, ip_), list(2, ip_)
              if (.not. s%fluid(a)) cycle
              b0 = list(3, ip_)
              if (list(5, ip_) == 1) b0 = a + 1
              do b = b0, list(4, ip_)
                if (.not. s%fluid(b)) cycle
                dx = s%x(a) - s%x(b)
                dz = s%z(a) - s%z(b)
                r2 = dx * dx + dz * dz
                if (r2 >= kern%support2 .or. r2 <= 1.0e-18_rp) cycle
                call kernel_eval(kern, sqrt(r2), wab, f)
                if (.not. mls) then
                  acc(1, a) = acc(1, a) + wab * v(b)
                  acc(2, a) = acc(2, a) + wab * s%m(b)
                  acc(1, b) = acc(1, b) + wab * v(a)
                  acc(2, b) = acc(2, b) + wab * s%m(a)
                else if (pass == 1) then
                  call add_moments(acc(:, a), wab * v(b), dx, dz)
                  call add_moments(acc(:, b), wab * v(a), -dx, -dz)
                else
                  wa = (beta(1, a) + beta(2, a) * dx + beta(3, a) * dz) * wab
                  wb = (beta(1, b) - beta(2, b) * dx - beta(3, b) * dz) * wab
                  rnew(a) = rnew(a) + s%m(b) * wa
                  rnew(b) = rnew(b) + s%m(a) * wb
                end if
              end do
            end do
          end do
        end do
        !$omp end do
        deallocate(list)
        !$omp end parallel
      end do
      if (mls .and. pass == 1) then
        do k = 1, n
          if (.not. s%fluid(k)) cycle
          acc(1, k) = acc(1, k) + w0 * v(k)
          call mls_beta(acc(:, k), beta(:, k), sing)
          if (sing) n_singular = n_singular + 1
        end do
      end if
    end do

    do k = 1, n
      if (.not. s%fluid(k)) cycle
      i = s%grid%order(k)
      if (mls) then
        st%rho(i) = rnew(k) + beta(1, k) * w0 * s%m(k)
      else
        st%rho(i) = (acc(2, k) + w0 * s%m(k)) / (acc(1, k) + w0 * v(k))
      end if
      st%p(i) = tait_pressure(st%rho(i), prm%rho0, prm%b, prm%gamma)
      st%c(i) = tait_sound_speed(st%rho(i), prm%rho0, prm%c0)
    end do
  end subroutine apply_density_filter

  pure subroutine add_moments(a, wv, dx, dz)
    real(rp), intent(inout) :: a(6)
    real(rp), intent(in) :: wv, dx, dz
    a(1) = a(1) + wv
    a(2) = a(2) + wv * dx
    a(3) = a(3) + wv * dz
    a(4) = a(4) + wv * dx * dx
    a(5) = a(5) + wv * dx * dz
    a(6) = a(6) + wv * dz * dz
  end subroutine add_moments

end module filter_loops
