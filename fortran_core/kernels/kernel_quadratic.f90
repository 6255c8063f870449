!> Quadratic kernel in 2D (Johnson et al. 1996), support 2h: W = 3/(2 pi h^2) (1 - q/2)^2.
module kernel_quadratic
  use sphjet_kinds, only: rp, pi
  implicit none
  private
  public :: quadratic_norm, quadratic_f, quadratic_dfdq

  real(rp), parameter :: quadratic_norm = 3.0_rp / (2.0_rp * pi)

contains

  pure elemental function quadratic_f(q) result(f)
    real(rp), intent(in) :: q
    real(rp) :: f
    f = max(1.0_rp - 0.5_rp * q, 0.0_rp)**2
  end function quadratic_f

  pure elemental function quadratic_dfdq(q) result(df)
    real(rp), intent(in) :: q
    real(rp) :: df
    df = -max(1.0_rp - 0.5_rp * q, 0.0_rp)
  end function quadratic_dfdq

end module kernel_quadratic
