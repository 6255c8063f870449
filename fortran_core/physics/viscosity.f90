!> Viscous pair terms.
!> Artificial viscosity (Monaghan 1992): Pi_ab = -alpha h cbar (u_ab . r_ab) / (rhobar (r^2 + eta^2))
!> for approaching pairs (u_ab . r_ab < 0), 0 otherwise; eta^2 = 0.01 h^2.
!> With the reconstruction (numerics.artificial_reconstruction), Pi takes the approach rate of
!> the two velocities extrapolated to the pair's midpoint with each particle's velocity gradient
!> (the idea of Rosswog 2015, MNRAS 448, 3628, with van Leer's limiter): a linear velocity field
!> leaves no jump there, so the resolved flow is damped at second order in h only.
!> Laminar viscosity (Lo & Shao 2002): du_a/dt += sum_b m_b 4 nu (r_ab . grad W) /
!> ((rho_a + rho_b)(r^2 + eta^2)) u_ab.
module viscosity
  use sphjet_kinds, only: rp
  implicit none
  private
  public :: artificial_pi, reconstructed_dq, laminar_factor

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

  !> The approach rate at the pair's midpoint. dq = (u_ab . r_ab) / (r^2 + eta^2) of the
  !> particles' velocities; ea, eb = (r_ab . G r_ab) / (r^2 + eta^2) with particle a's and b's
  !> velocity gradient G (du_i/dx_j): the jump each one's linear field predicts across the
  !> pair. The midpoint jump is dq - phi (ea + eb) / 2, with phi = 4 ea eb / (ea + eb)^2 where
  !> the two agree in sign and 0 where they do not (van Leer's limiter: phi = 1 for equal
  !> slopes, so a linear field gives 0). The result is kept between dq and 0: the damping of an
  !> approaching pair is at most the plain Pi's, and a receding pair gets none.
  pure function reconstructed_dq(dq, ea, eb) result(dm)
    real(rp), intent(in) :: dq, ea, eb
    real(rp) :: dm
    real(rp) :: s, phi
    s = ea + eb
    ! ea eb > 0 gives s^2 >= 4 ea eb > 0; the max only keeps the unused branch finite
    phi = merge(4.0_rp * ea * eb / max(s * s, tiny(s)), 0.0_rp, ea * eb > 0.0_rp)
    dm = min(0.0_rp, max(dq, dq - 0.5_rp * phi * s))
  end function reconstructed_dq

  !> Factor L such that du_a/dt += m_b L u_ab (and du_b/dt -= m_a L u_ab); f = (dW/dr)/r,
  !> inv_rhosum = 1 / (rho_a + rho_b), inv_r2eta = 1 / (r^2 + eta^2).
  pure function laminar_factor(nu, inv_rhosum, f, r2, inv_r2eta) result(l)
    real(rp), intent(in) :: nu, inv_rhosum, f, r2, inv_r2eta
    real(rp) :: l
    l = 4.0_rp * nu * inv_rhosum * (f * r2) * inv_r2eta
  end function laminar_factor

end module viscosity
