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
!> The particle part of the step (which fluid particle has the largest |a|, and max c) is a
!> scan that the integrator's own particle loops make (cfl_add, each thread over its share,
!> cfl_merge combining the shares in an order-free way: the same particle as one serial scan,
!> the last of equal |a|), so that it costs no pass of its own; cfl_time_step then needs no
!> particle field.
module time_step
  use sphjet_kinds, only: rp
  use sphjet_types, only: sph_params_t, state_t
  use surface_tension, only: csf_dt
  implicit none
  private
  public :: cfl_scan_t, cfl_add, cfl_merge, cfl_time_step, capped_step

  !> What the step needs of the particles: the fluid particle i with the largest |a|^2 = a2
  !> (the last one in particle order among equal ones) and its acceleration, and max c.
  type :: cfl_scan_t
    real(rp) :: a2 = -1.0_rp, ax = 0.0_rp, az = 0.0_rp, cmax = -1.0_rp
    integer :: i = 0
  end type cfl_scan_t

contains

  !> Particle i (an active fluid particle, particles taken in increasing i) into scan.
  pure subroutine cfl_add(scan, st, i)
    type(cfl_scan_t), intent(inout) :: scan
    type(state_t), intent(in) :: st
    integer, intent(in) :: i
    real(rp) :: a2
    a2 = st%ax(i) * st%ax(i) + st%az(i) * st%az(i)
    if (a2 >= scan%a2) then
      scan%a2 = a2
      scan%i = i
      scan%ax = st%ax(i)
      scan%az = st%az(i)
    end if
    scan%cmax = max(scan%cmax, st%c(i))
  end subroutine cfl_add

  !> The scan of another share of the particles into scan (either order, same result).
  pure subroutine cfl_merge(scan, part)
    type(cfl_scan_t), intent(inout) :: scan
    type(cfl_scan_t), intent(in) :: part
    real(rp) :: cmax
    cmax = max(scan%cmax, part%cmax)
    if (part%i > 0) then
      if (part%a2 > scan%a2 .or. (part%a2 == scan%a2 .and. part%i > scan%i)) scan = part
    end if
    scan%cmax = cmax
  end subroutine cfl_merge

  subroutine cfl_time_step(prm, scan, vmax, vgate, dt_f, dt_cv, dt_new)
    type(sph_params_t), intent(in) :: prm
    type(cfl_scan_t), intent(in) :: scan
    real(rp), intent(in) :: vmax
    real(rp), intent(in) :: vgate  !< speed of the gate in the next step [m/s]; 0 = none
    real(rp), intent(out) :: dt_f, dt_cv, dt_new
    real(rp) :: fmag

    if (scan%i > 0) then
      fmag = sqrt((scan%ax + prm%gravity%gx)**2 + (scan%az + prm%gravity%gz)**2)
    else
      fmag = sqrt(prm%gravity%gx**2 + prm%gravity%gz**2)
    end if
    if (fmag > 0.0_rp) then
      dt_f = sqrt(prm%numerics%h / fmag)
    else
      dt_f = huge(1.0_rp)
    end if
    if (scan%cmax > 0.0_rp) then
      dt_cv = prm%numerics%h / (scan%cmax + prm%numerics%h * vmax)
    else
      dt_cv = dt_f
    end if
    dt_new = prm%time_step%cfl * min(dt_f, dt_cv)
    if (prm%surface_tension%sigma > 0.0_rp) &
      dt_new = min(dt_new, csf_dt(prm%eos%rho0, prm%numerics%h, prm%surface_tension%sigma))
    ! The bulk viscosity's (numerics.bulk_viscosity) explicit diffusion bound, dt <= 0.125 h^2 / nu_b
    ! with nu_b = beta c0 h (Morris, Fox & Zhu 1997's viscous condition).
    if (prm%numerics%bulk_viscosity > 0.0_rp) dt_new = min(dt_new, &
      0.125_rp * prm%numerics%h / (prm%numerics%bulk_viscosity * prm%eos%c0))
    ! A moving gate crosses at most CFL h per step (legacy has no such bound: a gate faster
    ! than about h / dt then jumps over fluid particles and the run blows up).
    if (vgate > 0.0_rp) dt_new = min(dt_new, prm%time_step%cfl * prm%numerics%h / vgate)
  end subroutine cfl_time_step

  !> The variable step dt_new held at time_step%dt_max where that is set (> 0): a step that
  !> changes only where the CFL and force conditions ask for less than the cap. The variable
  !> step changes every step with the fastest particle anywhere, and in the round jets that
  !> jitter seeds the jet (cases/round_jet/README.md, "A step that does not jitter").
  pure real(rp) function capped_step(prm, dt_new)
    type(sph_params_t), intent(in) :: prm
    real(rp), intent(in) :: dt_new
    capped_step = dt_new
    if (prm%time_step%dt_max > 0.0_rp) capped_step = min(dt_new, prm%time_step%dt_max)
  end function capped_step

end module time_step
