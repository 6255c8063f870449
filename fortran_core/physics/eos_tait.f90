!> Tait equation of state as SPHysics sets it (Batchelor 1967; Monaghan 1994):
!> p = B [(rho/rho0)^gamma - 1], B = coef^2 rho0 g h_SWL / gamma (set by the case),
!> sound speed c = c0 (rho/rho0)^3 with c0 = sqrt(gamma B / rho0) (SPHysics' choice, exact
!> for gamma = 7: c^2 = dp/drho).
module eos_tait
  use sphjet_kinds, only: rp
  implicit none
  private
  public :: tait_pressure, tait_sound_speed, tait_density

contains

  pure elemental function tait_pressure(rho, rho0, b, gamma) result(p)
    real(rp), intent(in) :: rho, rho0, b, gamma
    real(rp) :: p, ratio
    ratio = rho / rho0
    if (gamma == 7.0_rp) then
      p = b * (ratio**7 - 1.0_rp)
    else
      p = b * (ratio**gamma - 1.0_rp)
    end if
  end function tait_pressure

  pure elemental function tait_sound_speed(rho, rho0, c0) result(c)
    real(rp), intent(in) :: rho, rho0, c0
    real(rp) :: c
    c = c0 * (rho / rho0)**3
  end function tait_sound_speed

  !> Inverse of tait_pressure: the density at pressure p.
  pure elemental function tait_density(p, rho0, b, gamma) result(rho)
    real(rp), intent(in) :: p, rho0, b, gamma
    real(rp) :: rho
    rho = rho0 * (1.0_rp + p / b)**(1.0_rp / gamma)
  end function tait_density

end module eos_tait
