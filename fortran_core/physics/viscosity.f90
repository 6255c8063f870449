!> Viscous pair terms.
!> Artificial viscosity (Monaghan 1992): Pi_ab = -alpha h cbar (u_ab . r_ab) / (rhobar (r^2 + eta^2))
!> for approaching pairs (u_ab . r_ab < 0), 0 otherwise; eta^2 = 0.01 h^2.
!> Laminar viscosity (Lo & Shao 2002): du_a/dt += sum_b m_b 4 nu (r_ab . grad W) /
!> ((rho_a + rho_b)(r^2 + eta^2)) u_ab.
module viscosity
  use sphjet_kinds, only: rp
  implicit none
  private
  public :: artificial_pi, laminar_factor

contains

  !> Pi_ab from the pair's approach rate dq = (u_ab . r_ab) / (r^2 + eta^2) and 1 / rhobar
  !> (the pair loops form both once per pair: dq also gives the time-step control its max,
  !> and 1 / rhobar serves XSPH too, so that a pair costs two divisions, not five).
  pure function artificial_pi(alpha, h, cbar, inv_rhobar, dq) result(pv)
    real(rp), intent(in) :: alpha, h, cbar, inv_rhobar, dq
    real(rp) :: pv
    ! a select of a value computed for every pair, not a branch: with the formula inside the
    ! merge, gfortran loads cbar's and rhobar's operands only where dot <= 0, a masked
    ! gather the vectoriser rejects, and the pair loops stayed scalar
    pv = -alpha * h * cbar * dq * inv_rhobar
    pv = merge(pv, 0.0_rp, dq <= 0.0_rp)
  end function artificial_pi

  !> Factor L such that du_a/dt += m_b L u_ab (and du_b/dt -= m_a L u_ab); f = (dW/dr)/r,
  !> inv_rhosum = 1 / (rho_a + rho_b), inv_r2eta = 1 / (r^2 + eta^2).
  pure function laminar_factor(nu, inv_rhosum, f, r2, inv_r2eta) result(l)
    real(rp), intent(in) :: nu, inv_rhosum, f, r2, inv_r2eta
    real(rp) :: l
    l = 4.0_rp * nu * inv_rhosum * (f * r2) * inv_r2eta
  end function laminar_factor

end module viscosity
