!> Tensile-instability correction (Monaghan 2000) as SPHysics applies it: the pressure term
!> p_a/rho_a^2 + p_b/rho_b^2 gains (R_a + R_b) (W_ab / W(dp))^4 with
!> R = 0.01 p/rho^2 for p > 0 and 0.2 |p|/rho^2 for p <= 0.
module tensile_correction
  use sphjet_kinds, only: rp
  implicit none
  private
  public :: tensile_term, tensile_r

contains

  pure elemental function tensile_r(p, pr) result(r)
    real(rp), intent(in) :: p   !< pressure
    real(rp), intent(in) :: pr  !< p / rho^2
    real(rp) :: r
    if (p > 0.0_rp) then
      r = 0.01_rp * pr
    else
      r = 0.2_rp * abs(pr)
    end if
  end function tensile_r

  pure function tensile_term(r_a, r_b, w, inv_wdp) result(t)
    real(rp), intent(in) :: r_a, r_b, w, inv_wdp
    real(rp) :: t, fab
    fab = (w * inv_wdp)**2
    t = (r_a + r_b) * fab * fab
  end function tensile_term

end module tensile_correction
