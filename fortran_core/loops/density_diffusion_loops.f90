!> Density diffusion (physics/density_diffusion.f90) over the sorted particles: one sweep over
!> the pairs the rates sweep kept (the same pairs, W and F), fluid-fluid pairs only (a wall
!> particle's density is the boundary scheme's), and the sums added to the density rates of
!> the real slots. The volume V_b is m_b / rho_b with the masses of the sorted state: in the
!> axisymmetric mode the planar ones (m / (2 pi r)), so that the sum is the diffusion in the
!> meridian plane. Like every traversal here, bitwise independent of the thread count.
module density_diffusion_loops
  use sphjet_kinds, only: rp
  use sphjet_types, only: sph_params_t
  use sphjet_kernels, only: kernel_t
  use sorted_state, only: sorted_t, R_AR
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_ANY_FLUID, SWEEP_REUSE
  use density_diffusion, only: diffusion_pair
  implicit none
  private
  public :: density_diffusion_rates

  !> The sweep's body: 2 delta h c0, the volumes, densities and the sums.
  type, extends(pair_body_t) :: diffusion_body_t
    real(rp) :: coef = 0.0_rp
    real(rp), pointer, contiguous :: rho(:) => null()
    real(rp), allocatable :: v(:), d(:)
  contains
    procedure :: visit => diffusion_visit
  end type diffusion_body_t

contains

  !> Adds the diffusion to s%rate(R_AR, :) of the real fluid slots (slot order k with
  !> s%grid%order(k) <= n_state). The pairs are the ones the last SWEEP_KEEP sweep kept at
  !> these positions (compute_rates keeps them when the diffusion is on).
  subroutine density_diffusion_rates(prm, kern, s, n_state)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(sorted_t), intent(inout), target :: s
    integer, intent(in) :: n_state
    type(diffusion_body_t) :: body
    integer :: n, k
    real(rp) :: red
    n = s%n
    body%coef = 2.0_rp * prm%numerics%density_diffusion * prm%numerics%h * prm%eos%c0
    body%rho => s%rho
    allocate(body%v(n), body%d(n))
    body%v = s%m(1:n) / s%rho(1:n)
    body%d = 0.0_rp
    red = 0.0_rp
    call pair_sweep(s, kern, PAIRS_ANY_FLUID, body, red, SWEEP_REUSE)
    !$omp parallel do schedule(static)
    do k = 1, n
      if (s%grid%order(k) > n_state .or. .not. s%fluid(k)) cycle
      s%rate(R_AR, k) = s%rate(R_AR, k) + body%d(k)
    end do
    !$omp end parallel do
  end subroutine density_diffusion_rates

  !> The fluid pairs of one row task: d_a += term V_b, d_b -= term V_a.
  subroutine diffusion_visit(self, pl, red)
    class(diffusion_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    integer :: k, a, b
    real(rp) :: t
    do k = 1, pl%n
      if (pl%mixed(k)) cycle
      a = pl%a(k)
      b = pl%b(k)
      t = diffusion_pair(self%coef, self%rho(a), self%rho(b), pl%f(k))
      self%d(a) = self%d(a) + t * self%v(b)
      self%d(b) = self%d(b) - t * self%v(a)
    end do
    red = max(red, 0.0_rp)
  end subroutine diffusion_visit

end module density_diffusion_loops
