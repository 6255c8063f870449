!> Wendland C2 kernel in 2D (Wendland 1995), support 2h:
!> W = 7/(4 pi h^2) (1 + 2q) (1 - q/2)^4, q = r/h.
!> Legacy SPHysics writes the constant as 0.557/h^2 (7/(4 pi) = 0.55704...); this fork uses
!> the exact value so that the kernel integrates to 1.
module kernel_wendland
  use sphjet_kinds, only: rp, pi
  implicit none
  private
  public :: wendland_norm, wendland_f, wendland_dfdq_q

  real(rp), parameter :: wendland_norm = 7.0_rp / (4.0_rp * pi)  !< times 1/h^2 in 2D

contains

  pure elemental function wendland_f(q) result(f)
    real(rp), intent(in) :: q
    real(rp) :: f, t
    t = max(1.0_rp - 0.5_rp * q, 0.0_rp)
    f = (1.0_rp + 2.0_rp * q) * t**4
  end function wendland_f

  !> (df/dq) / q, without a division: F = (dW/dr)/r = norm/h^4 (df/dq)/q.
  pure elemental function wendland_dfdq_q(q) result(dfq)
    real(rp), intent(in) :: q
    real(rp) :: dfq, t
    t = max(1.0_rp - 0.5_rp * q, 0.0_rp)
    dfq = -5.0_rp * t**3
  end function wendland_dfdq_q

end module kernel_wendland
