!> The driven nozzle of sphjet's jet cases (cases/jet/README.md): the fluid that fills the
!> nozzle is a plug pushed out of the orifice at the jet speed u0. A fluid particle is in the
!> plug while its position lies upstream of the orifice line and within the plug's half-width
!> of the axis:
!>   s = (r - r0) . e < 0   and   |(r - r0) x e| <= half_width,
!> r0 the orifice centre, e the unit jet axis (flow direction). The test has no memory: fluid
!> that comes back upstream into that strip is driven again (with the plug's velocity, see
!> plug_step below); keep other fluid regions out of it.
module nozzle_drive
  use sphjet_kinds, only: rp
  use sphjet_types, only: sph_params_t, state_t
  implicit none
  private
  public :: in_driven_nozzle, plug_step

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

  !> A fluid particle whose start-of-step position lies in a driven nozzle (in_driven_nozzle),
  !> after the predictor-corrector's half_steps (or the leapfrog's kicks, with its whole step as
  !> dt2): it moves rigidly with the plug velocity instead, r = r^n + dt2 u_plug, u = u_plug
  !> (and u^n := u_plug, so that the corrector's extrapolation keeps u_plug); its density still
  !> follows continuity.
  subroutine plug_step(prm, st, i, dt2)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer, intent(in) :: i
    real(rp), intent(in) :: dt2
    st%u(i) = prm%nozzle%u * prm%nozzle%ex
    st%w(i) = prm%nozzle%u * prm%nozzle%ez
    st%x(i) = st%xo(i) + dt2 * st%u(i)
    st%z(i) = st%zo(i) + dt2 * st%w(i)
    ! The corrector's u = 2 u^{n+1/2} - u^n must give the plug's velocity also for a
    ! particle that entered the plug with another one.
    st%uo(i) = st%u(i)
    st%wo(i) = st%w(i)
  end subroutine plug_step

end module nozzle_drive
