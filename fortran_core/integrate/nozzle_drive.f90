!> The driven nozzle of sphjet's jet cases (cases/jet/README.md): the fluid that fills the
!> nozzle is a plug pushed out of the orifice at the jet speed u0. A fluid particle is in the
!> plug while its position lies upstream of the orifice line and within the plug's half-width
!> of the axis:
!>   s = (r - r0) . e < 0   and   |(r - r0) x e| <= half_width,
!> r0 the orifice centre, e the unit jet axis (flow direction). The test has no memory: fluid
!> that comes back upstream into that strip is driven again (with the plug's velocity, see
!> predictor_corrector's plug_step); keep other fluid regions out of it.
module nozzle_drive
  use sphjet_kinds, only: rp
  use sphjet_types, only: sph_params_t
  implicit none
  private
  public :: in_driven_nozzle

contains

  pure logical function in_driven_nozzle(prm, x, z)
    type(sph_params_t), intent(in) :: prm
    real(rp), intent(in) :: x, z
    real(rp) :: rx, rz
    rx = x - prm%nozzle%x0
    rz = z - prm%nozzle%z0
    in_driven_nozzle = rx * prm%nozzle%ex + rz * prm%nozzle%ez < 0.0_rp .and. &
                       abs(rx * prm%nozzle%ez - rz * prm%nozzle%ex) <= prm%nozzle%half_width
  end function in_driven_nozzle

end module nozzle_drive
