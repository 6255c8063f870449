!> Density filters (SPHysics): Shepard (zeroth order) and moving least squares (first order,
!> Colagrossi & Landrini 2003). The MLS correction vector beta = A^{-1} e1 with
!> A = sum_b W_ab V_b [1, x_ab, z_ab; x_ab, x_ab^2, x_ab z_ab; z_ab, x_ab z_ab, z_ab^2]
!> (self term included); a (near) singular A falls back to the Shepard weight 1/A_11.
module density_filter
  use sphjet_kinds, only: rp
  implicit none
  private
  public :: mls_beta

contains

  !> a = (A11, A12, A13, A22, A23, A33) of the symmetric matrix.
  pure subroutine mls_beta(a, beta, singular)
    real(rp), intent(in) :: a(6)
    real(rp), intent(out) :: beta(3)
    logical, intent(out) :: singular
    real(rp) :: c11, c12, c13, det, scale
    ! cofactors of the first column (A symmetric, so the first column of the inverse)
    c11 = a(4) * a(6) - a(5) * a(5)
    c12 = -(a(2) * a(6) - a(5) * a(3))
    c13 = a(2) * a(5) - a(4) * a(3)
    det = a(1) * c11 + a(2) * c12 + a(3) * c13
    scale = abs(a(1) * a(4) * a(6))
    singular = .not. (abs(det) > 1.0e-12_rp * scale .and. scale > 0.0_rp)
    if (singular) then
      beta = [1.0_rp / a(1), 0.0_rp, 0.0_rp]
    else
      beta = [c11, c12, c13] / det
    end if
  end subroutine mls_beta

end module density_filter
