!> Density diffusion (physics/density_diffusion.f90) over the sorted particles: one sweep over
!> the pairs the rates sweep kept (the same pairs, W and F), fluid-fluid pairs only (a wall
!> particle's density is the boundary scheme's), and the sums added to the density rates of
!> the real slots. The volume V_b is m_b / rho_b with the masses of the sorted state: in the
!> axisymmetric mode the planar ones (m / (2 pi r)), so that the sum is the diffusion in the
!> meridian plane (which case_build.cpp refuses for now). Like every traversal here, bitwise
!> independent of the thread count.
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

  !> The sweep's body: 2 delta h c0, the volumes and the sorted state, whose density rates
  !> the pairs add to.
  type, extends(pair_body_t) :: diffusion_body_t
    real(rp) :: coef = 0.0_rp
    type(sorted_t), pointer :: s => null()
    real(rp), allocatable :: v(:)
  contains
    procedure :: visit => diffusion_visit
  end type diffusion_body_t

contains

  !> Adds the diffusion to s%rate(R_AR, :) over the pairs the last SWEEP_KEEP sweep kept at
  !> these positions (compute_rates keeps them when the diffusion is on: rates_keep_pairs).
  !> Only fluid slots receive anything; image slots' sums are not scattered back.
  subroutine density_diffusion_rates(prm, kern, s)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(sorted_t), intent(inout), target :: s
    type(diffusion_body_t) :: body
    real(rp) :: red
    body%coef = 2.0_rp * prm%numerics%density_diffusion * prm%numerics%h * prm%eos%c0
    body%s => s
    body%v = s%m(1:s%n) / s%rho(1:s%n)
    red = 0.0_rp
    call pair_sweep(s, kern, PAIRS_ANY_FLUID, body, red, SWEEP_REUSE)
  end subroutine density_diffusion_rates

  !> The fluid pairs of one row task: drho_a/dt += term V_b, drho_b/dt -= term V_a.
  subroutine diffusion_visit(self, pl, red)
    class(diffusion_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    integer :: k, a, b
    real(rp) :: t
    associate (r => self%s%rate, rho => self%s%rho, v => self%v)
      do k = 1, pl%n
        if (pl%mixed(k)) cycle
        a = pl%a(k)
        b = pl%b(k)
        t = diffusion_pair(self%coef, rho(a), rho(b), pl%f(k))
        r(R_AR, a) = r(R_AR, a) + t * v(b)
        r(R_AR, b) = r(R_AR, b) - t * v(a)
      end do
    end associate
    red = max(red, 0.0_rp)
  end subroutine diffusion_visit

end module density_diffusion_loops
