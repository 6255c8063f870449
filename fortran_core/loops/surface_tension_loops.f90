!> CSF surface tension (Morris 2000) pair loops. Placeholder until the module lands:
!> it refuses nothing and adds nothing; sigma > 0 is refused by the C interface meanwhile.
module surface_tension_loops
  use sphjet_types, only: sph_params_t, state_t
  use sphjet_kernels, only: kernel_t
  use sorted_state, only: sorted_t
  implicit none
  private
  public :: surface_tension_rates

contains

  subroutine surface_tension_rates(prm, kern, st, s)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout) :: st
    type(sorted_t), intent(inout) :: s
    if (.false.) print *, prm%sigma, kern%h, st%n, s%n
  end subroutine surface_tension_rates

end module surface_tension_loops
