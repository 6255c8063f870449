!> Gaussian kernel in 2D, W = 1/(pi h^2) exp(-q^2), cut at q = 2 as in SPHysics.
!> The cut drops a fraction exp(-4) = 1.8% of its integral (kept, as legacy does).
module kernel_gaussian
  use sphjet_kinds, only: rp, pi
  implicit none
  private
  public :: gaussian_norm, gaussian_f, gaussian_dfdq

  real(rp), parameter :: gaussian_norm = 1.0_rp / pi

contains

  pure elemental function gaussian_f(q) result(f)
    real(rp), intent(in) :: q
    real(rp) :: f
    f = merge(exp(-q * q), 0.0_rp, q < 2.0_rp)
  end function gaussian_f

  pure elemental function gaussian_dfdq(q) result(df)
    real(rp), intent(in) :: q
    real(rp) :: df
    df = merge(-2.0_rp * q * exp(-q * q), 0.0_rp, q < 2.0_rp)
  end function gaussian_dfdq

end module kernel_gaussian
