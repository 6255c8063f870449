!> Density diffusion in the continuity equation (delta-SPH; Molteni & Colagrossi 2009, Comput.
!> Phys. Commun. 180, 861; the form of Antuono et al. 2010, Comput. Phys. Commun. 181, 532):
!>   drho_a/dt += delta h c0 sum_b psi_ab . grad_a W_ab V_b,
!>   psi_ab = 2 (rho_b - rho_a) (r_b - r_a) / |r_b - r_a|^2.
!> With grad_a W_ab = F_ab (r_a - r_b), F = (dW/dr)/r <= 0, the pair's term is
!>   2 delta h c0 (rho_a - rho_b) F_ab V_b:
!> density flows from the denser particle to the lighter one, as a Laplacian of rho with a
!> diffusivity of order delta h c0, which vanishes with h. A uniform density gives exactly
!> zero, on any particle arrangement, and the pair form conserves sum_a V_a rho_a. Without
!> gravity (the jets, drops and columns) this is the whole correction; with gravity the
!> hydrostatic density gradient diffuses too, which Antuono et al. (2012) and Fourtakas et al.
!> (2019) correct and this form does not (cases/CASE_FORMAT.md says so).
module density_diffusion
  use sphjet_kinds, only: rp
  implicit none
  private
  public :: diffusion_pair

contains

  !> The term pair (a, b) adds to drho_a/dt per unit volume V_b of b: coef (rho_a - rho_b) F,
  !> coef = 2 delta h c0 [m^2/s]; b's term per V_a is its negative.
  pure elemental function diffusion_pair(coef, rho_a, rho_b, f) result(d)
    real(rp), intent(in) :: coef, rho_a, rho_b, f
    real(rp) :: d
    d = coef * (rho_a - rho_b) * f
  end function diffusion_pair

end module density_diffusion
