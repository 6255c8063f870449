!> Cubic B-spline kernel in 2D (Monaghan & Lattanzio 1985), support 2h:
!> W = 10/(7 pi h^2) (1 - 1.5 q^2 + 0.75 q^3) for q < 1, 10/(7 pi h^2) (2 - q)^3 / 4 for 1 <= q < 2.
module kernel_cubic
  use sphjet_kinds, only: rp, pi
  implicit none
  private
  public :: cubic_norm, cubic_f, cubic_dfdq

  real(rp), parameter :: cubic_norm = 10.0_rp / (7.0_rp * pi)

contains

  pure elemental function cubic_f(q) result(f)
    real(rp), intent(in) :: q
    real(rp) :: f
    if (q < 1.0_rp) then
      f = 1.0_rp - 1.5_rp * q * q + 0.75_rp * q**3
    else if (q < 2.0_rp) then
      f = 0.25_rp * (2.0_rp - q)**3
    else
      f = 0.0_rp
    end if
  end function cubic_f

  pure elemental function cubic_dfdq(q) result(df)
    real(rp), intent(in) :: q
    real(rp) :: df
    if (q < 1.0_rp) then
      df = -3.0_rp * q + 2.25_rp * q * q
    else if (q < 2.0_rp) then
      df = -0.75_rp * (2.0_rp - q)**2
    else
      df = 0.0_rp
    end if
  end function cubic_dfdq

end module kernel_cubic
