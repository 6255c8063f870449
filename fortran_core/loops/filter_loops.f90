!> Density filters over fluid-fluid pairs (boundary particles neither filter nor are used):
!>   Shepard: rho_a = sum_b m_b W_ab / sum_b V_b W_ab
!>   MLS:     rho_a = sum_b m_b W_ab (beta0 + beta1 . (r_a - r_b)), beta = A^{-1} e1
!> sums include the particle itself (W(0)), volumes V_b = m_b/rho_b at the time of the filter.
module filter_loops
  use sphjet_kinds, only: rp, ip, KIND_FLUID, FILTER_SHEPARD, FILTER_MLS
  use sphjet_types, only: sph_params_t, state_t
  use sphjet_kernels, only: kernel_t, kernel_eval, kernel_w0
  use sorted_state, only: sorted_t
  use list_rebuild, only: gather_sorted
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_FLUID, SWEEP_FRESH, &
                       SWEEP_KEEP, SWEEP_REUSE
  use density_filter, only: mls_beta
  use eos_tait, only: tait_pressure, tait_sound_speed
  implicit none
  private
  public :: apply_density_filter

  !> The filter pair loop body: Shepard sums, or MLS moments (pass 1) and the corrected
  !> density sum (pass 2).
  type, extends(pair_body_t) :: filter_body_t
    type(sorted_t), pointer :: s => null()
    logical :: mls = .false.
    integer :: pass = 1
    real(rp), allocatable :: acc(:, :), beta(:, :), v(:), rnew(:)
  contains
    procedure :: visit => filter_visit
  end type filter_body_t

contains

  subroutine apply_density_filter(prm, kern, st, s, n_singular)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout) :: st
    type(sorted_t), intent(inout), target :: s
    integer, intent(out) :: n_singular
    real(rp), allocatable :: acc(:, :), beta(:, :), v(:), rnew(:)
    type(filter_body_t) :: body
    integer :: n, k, i, pass, npass
    real(rp) :: w0, red
    logical :: mls, sing

    n_singular = 0
    if (all(prm%numerics%density_filter /= [FILTER_SHEPARD, FILTER_MLS])) return
    mls = prm%numerics%density_filter == FILTER_MLS
    call gather_sorted(st, prm%numerics%h, s, prm)
    n = s%n
    w0 = kernel_w0(kern)
    allocate(body%v(n), body%rnew(n), body%beta(3, n))
    body%v = s%m(1:n) / s%rho(1:n)
    npass = merge(2, 1, mls)
    allocate(body%acc(merge(6, 2, mls), n))
    body%mls = mls
    body%s => s
    do pass = 1, npass
      body%pass = pass
      body%acc = 0.0_rp
      body%rnew = 0.0_rp
      red = 0.0_rp
      ! MLS: pass 2 visits the pairs (and W) pass 1 found
      call pair_sweep(s, kern, PAIRS_FLUID, body, red, &
                      merge(merge(SWEEP_KEEP, SWEEP_REUSE, pass == 1), SWEEP_FRESH, mls))
      if (mls .and. pass == 1) then
        do k = 1, n
          if (.not. s%fluid(k)) cycle
          if (s%src_slot(k) /= k) then   ! an image: its sums (no image-image pairs) are discarded
            body%beta(:, k) = 0.0_rp
            cycle
          end if
          body%acc(1, k) = body%acc(1, k) + w0 * body%v(k)
          call mls_beta(body%acc(:, k), body%beta(:, k), sing)
          if (sing) n_singular = n_singular + 1
        end do
      end if
    end do
    call move_alloc(body%acc, acc)
    call move_alloc(body%v, v)
    call move_alloc(body%beta, beta)
    call move_alloc(body%rnew, rnew)

    do k = 1, n
      if (.not. s%fluid(k)) cycle
      i = s%grid%order(k)
      if (i > st%n) cycle   ! an image slot (particle_images.f90)
      if (mls) then
        st%rho(i) = rnew(k) + beta(1, k) * w0 * s%m(k)
      else
        st%rho(i) = (acc(2, k) + w0 * s%m(k)) / (acc(1, k) + w0 * v(k))
      end if
      st%p(i) = tait_pressure(st%rho(i), prm%eos%rho0, prm%eos%b, prm%eos%gamma)
      st%c(i) = tait_sound_speed(st%rho(i), prm%eos%rho0, prm%eos%c0)
    end do
  end subroutine apply_density_filter

  !> The pairs of one row task: Shepard sums (kernel-weighted volumes and masses), MLS pass 1
  !> moments, or MLS pass 2 corrected density sums, into both particles of each pair.
  subroutine filter_visit(self, pl, red)
    class(filter_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    integer :: k
    real(rp) :: wa, wb
    associate (acc => self%acc, v => self%v, beta => self%beta, rnew => self%rnew, m => self%s%m)
      do k = 1, pl%n
        associate (a => pl%a(k), b => pl%b(k), w => pl%w(k))
          if (.not. self%mls) then
            acc(1, a) = acc(1, a) + w * v(b)
            acc(2, a) = acc(2, a) + w * m(b)
            acc(1, b) = acc(1, b) + w * v(a)
            acc(2, b) = acc(2, b) + w * m(a)
          else if (self%pass == 1) then
            call add_moments(acc(:, a), w * v(b), pl%dx(k), pl%dz(k))
            call add_moments(acc(:, b), w * v(a), -pl%dx(k), -pl%dz(k))
          else
            wa = (beta(1, a) + beta(2, a) * pl%dx(k) + beta(3, a) * pl%dz(k)) * w
            wb = (beta(1, b) - beta(2, b) * pl%dx(k) - beta(3, b) * pl%dz(k)) * w
            rnew(a) = rnew(a) + m(b) * wa
            rnew(b) = rnew(b) + m(a) * wb
          end if
        end associate
      end do
    end associate
    red = max(red, 0.0_rp)
  end subroutine filter_visit

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
