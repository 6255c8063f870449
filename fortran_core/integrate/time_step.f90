!> Variable time step (paper eqs 30-32, SPHysics variable_time_step):
!>   dt_f  = sqrt(h / |f|), f the acceleration (gravity included) of the fluid particle whose
!>           pair acceleration |a| (gravity excluded) is largest - SPHysics' choice, kept for
!>           parity; the paper writes min over all particles of sqrt(h/|f_a|);
!>   dt_cv = h / (max_a c_a + h max_ab (u_ab . r_ab)/(r_ab^2 + eta^2));
!>   dt    = CFL min(dt_f, dt_cv).
!> With surface tension (sigma > 0) the step is further capped by the capillary limit of
!> Brackbill et al. (1992) / Morris (2000): dt <= 0.25 sqrt(rho0 h^3 / (2 pi sigma)), the time
!> a capillary wave of wavelength ~h needs to cross a quarter of h. This is a departure from
!> the paper's eqs 30-32 (which have no capillary term): without it a run whose capillary
!> speed sqrt(2 pi sigma / (rho0 h)) approaches c0 (fine resolution, strong sigma) has no
!> bound on the explicit surface-tension step. dt_f and dt_cv are reported unchanged.
!> With a moving gate (moving boundary particles) the step is also capped at CFL h / |v_gate|.
module time_step
  use sphjet_kinds, only: rp, ip, KIND_FLUID
  use sphjet_types, only: sph_params_t, state_t
  use surface_tension, only: csf_dt
  implicit none
  private
  public :: cfl_time_step

contains

  subroutine cfl_time_step(prm, st, vmax, vgate, dt_f, dt_cv, dt_new)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(in) :: st
    real(rp), intent(in) :: vmax
    real(rp), intent(in) :: vgate  !< speed of the gate in the next step [m/s]; 0 = none
    real(rp), intent(out) :: dt_f, dt_cv, dt_new
    integer :: i, imax
    real(rp) :: amax, a2, cmax, fmag

    amax = -1.0_rp
    cmax = -1.0_rp
    imax = 0
    do i = st%nb + 1, st%n
      if (st%active(i) == 0 .or. st%kind(i) /= KIND_FLUID) cycle
      a2 = st%ax(i) * st%ax(i) + st%az(i) * st%az(i)
      if (a2 >= amax) then
        amax = a2
        imax = i
      end if
      cmax = max(cmax, st%c(i))
    end do
    if (imax > 0) then
      fmag = sqrt((st%ax(imax) + prm%gx)**2 + (st%az(imax) + prm%gz)**2)
    else
      fmag = sqrt(prm%gx**2 + prm%gz**2)
    end if
    if (fmag > 0.0_rp) then
      dt_f = sqrt(prm%h / fmag)
    else
      dt_f = huge(1.0_rp)
    end if
    if (cmax > 0.0_rp) then
      dt_cv = prm%h / (cmax + prm%h * vmax)
    else
      dt_cv = dt_f
    end if
    dt_new = prm%cfl * min(dt_f, dt_cv)
    if (prm%sigma > 0.0_rp) dt_new = min(dt_new, csf_dt(prm%rho0, prm%h, prm%sigma))
    ! A moving gate crosses at most CFL h per step (legacy has no such bound: a gate faster
    ! than about h / dt then jumps over fluid particles and the run blows up).
    if (vgate > 0.0_rp) dt_new = min(dt_new, prm%cfl * prm%h / vgate)
  end subroutine cfl_time_step

end module time_step
