!> Where a driven nozzle's plug is (cases/jet/README.md): a point is in the plug while it lies
!> upstream of the orifice line and within the plug's half-width of the jet axis,
!>   s = (r - r0) . e < 0   and   |(r - r0) x e| <= half_width,
!> r0 the orifice centre, e the unit jet axis (flow direction). The nozzle drive
!> (integrate/nozzle_drive.f90) moves such fluid with the plug; the surface tension's free
!> bodies (loops/surface_tension_loops.f90) count a body that holds such fluid as held.
module nozzle_geometry
  use sphjet_kinds, only: rp
  use sphjet_types, only: sph_params_t
  implicit none
  private
  public :: past_orifice, in_driven_nozzle

contains

  !> The signed distance of (x, z) past the orifice line along the jet axis, s = (r - r0) . e.
  pure real(rp) function past_orifice(prm, x, z)
    type(sph_params_t), intent(in) :: prm
    real(rp), intent(in) :: x, z
    past_orifice = (x - prm%nozzle%x0) * prm%nozzle%ex + (z - prm%nozzle%z0) * prm%nozzle%ez
  end function past_orifice

  !> Whether (x, z) lies in the driven plug (upstream of the orifice line, within half_width
  !> of the axis). Meaningful only with a nozzle (prm%nozzle%u > 0).
  pure logical function in_driven_nozzle(prm, x, z)
    type(sph_params_t), intent(in) :: prm
    real(rp), intent(in) :: x, z
    in_driven_nozzle = past_orifice(prm, x, z) < 0.0_rp .and. &
                       abs((x - prm%nozzle%x0) * prm%nozzle%ez - (z - prm%nozzle%z0) * prm%nozzle%ex) &
                       <= prm%nozzle%half_width
  end function in_driven_nozzle

end module nozzle_geometry
