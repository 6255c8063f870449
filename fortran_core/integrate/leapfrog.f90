!> Kick-drift-kick leapfrog with one evaluation of the rates per step
!> (numerics.integrator = "leapfrog"), for cases of fluid particles alone:
!>   kick     u^{n+1/2} = u^n + dt/2 (a^n + g),     rho^{n+1/2} = rho^n + dt/2 drho^n/dt
!>   drift    r^{n+1} = r^n + dt (u^{n+1/2} + XSPH^n)
!>   rates    a^{n+1}, drho^{n+1}/dt at r^{n+1}, with the velocity and density predicted to
!>            the step's end, u* = u^{n+1/2} + dt/2 (a^n + g), rho* = rho^{n+1/2} + dt/2 drho^n/dt
!>   kick     u^{n+1} = u^{n+1/2} + dt/2 (a^{n+1} + g), rho^{n+1} = rho^{n+1/2} + dt/2 drho^{n+1}/dt
!> The rates of the step's end are those of the next step's start: the state's ax, az, ar
!> and XSPH hold them between steps (info%rates_kept = 1), and the driver keeps them in a
!> checkpoint, so that a resumed run goes on bitwise. Where they are not kept (the first
!> step, or after the driver added, split or removed particles or filtered the densities)
!> the step evaluates them first, at the state as it is. For forces of the positions alone
!> this is the velocity Verlet (symplectic, second order). Here the density's rate depends on
!> the velocities and the pressure force on the density, and both are evaluated once, from the
!> prediction: for an oscillation y' = i omega y the step is a predict-evaluate-correct one,
!> amplification 1 + (omega dt)^4 / 4 per step, where the predictor-corrector
!> (predictor_corrector.f90, Monaghan 1989: the explicit midpoint rule, two evaluations per
!> step) has 1 + (omega dt)^4 / 8. So the sound waves need damping: the driver refuses the
!> leapfrog without the bulk viscosity (numerics.bulk_viscosity), and measured that without it
!> the round jets' column at rest grows to the capillary speed in 45 ms where with it the
!> column stays as still as with the predictor-corrector. A driven nozzle moves its particles
!> as a rigid plug, as there; boundary particles are not advanced (the driver refuses the key
!> with them).
module leapfrog
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use sphjet_kinds, only: rp, ip, SPH_ERR_ARGUMENT
  use sphjet_types, only: sph_params_t, state_t, sph_step_info_t
  use sphjet_kernels, only: kernel_t
  use sorted_state, only: sorted_t
  use rates, only: compute_rates
  use time_step, only: cfl_scan_t, cfl_add, cfl_time_step, capped_step
  use state_checks, only: check_domain, fold_into_domain, reflect_at_axis
  use fluid_update, only: eos_one, moving_fluid
  use nozzle_drive, only: in_driven_nozzle, plug_step
  implicit none
  private
  public :: lf_step

contains

  !> One step of the leapfrog (above) from info%time by info%dt; info%rates_kept in: 1 when
  !> st%ax, az, ar, xsph_u, xsph_w hold the rates of the state as it is; out: 1, or 0 when
  !> the step removed particles (their neighbours' rates then miss them).
  subroutine lf_step(prm, kern, st, s, info, status)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout), target :: st
    type(sorted_t), intent(inout) :: s
    type(sph_step_info_t), intent(inout) :: info
    integer(ip), intent(out) :: status
    real(rp) :: dt, dt2, vmax, dtf, dtcv, dt_new
    type(cfl_scan_t) :: scan
    integer :: i

    status = SPH_ERR_ARGUMENT
    if (st%nb > 0) return
    dt = info%dt
    dt2 = 0.5_rp * dt
    vmax = 0.0_rp
    if (info%rates_kept == 0) call compute_rates(prm, kern, st, s, vmax)

    ! the first kick, the drift and the prediction; the half-step values in uo, wo, rhoo, the
    ! start-of-step position (the plug's test, as the predictor-corrector's) in xo, zo
    !$omp parallel do schedule(static)
    do i = 1, st%n
      if (.not. moving_fluid(st, i)) cycle
      st%xo(i) = st%x(i)
      st%zo(i) = st%z(i)
      st%uo(i) = st%u(i) + dt2 * (st%ax(i) + prm%gravity%gx)
      st%wo(i) = st%w(i) + dt2 * (st%az(i) + prm%gravity%gz)
      st%rhoo(i) = st%rho(i) + dt2 * st%ar(i)
      st%x(i) = st%x(i) + dt * (st%uo(i) + st%xsph_u(i))
      st%z(i) = st%z(i) + dt * (st%wo(i) + st%xsph_w(i))
      call half_kick(prm, st, i, dt)   ! the prediction
    end do
    !$omp end parallel do
    call reflect_at_axis(prm, st)   ! a ring that crossed the axis, before its rates

    vmax = 0.0_rp
    call compute_rates(prm, kern, st, s, vmax)

    ! the time-step scan of the new rates (one thread: its order is the particles'), then the
    ! second kick
    do i = 1, st%n
      if (moving_fluid(st, i)) call cfl_add(scan, st, i)
    end do
    !$omp parallel do schedule(static)
    do i = 1, st%n
      if (moving_fluid(st, i)) call half_kick(prm, st, i, dt)
    end do
    !$omp end parallel do
    info%rates_kept = 1

    call cfl_time_step(prm, scan, vmax, 0.0_rp, dtf, dtcv, dt_new)
    info%dt_f = dtf
    info%dt_cv = dtcv
    info%dt_new = dt_new
    info%visc_dt = vmax
    info%dt_next = merge(capped_step(prm, dt_new), dt, prm%time_step%variable_dt /= 0)

    call fold_into_domain(prm, st)   ! periodic z (the axis: reflected after the drift, above)
    call check_domain(prm, st, info%n_removed, info%bad_particle, status)
    if (info%n_removed > 0) then
      ! as the predictor-corrector: the pairs listed again, and the rates evaluated again
      s%built = .false.
      if (associated(st%list_x)) st%list_x = ieee_value(1.0_rp, ieee_quiet_nan)
      if (associated(st%list_z)) st%list_z = ieee_value(1.0_rp, ieee_quiet_nan)
      info%rates_kept = 0
    end if
    info%bad_cause = status
  end subroutine lf_step

  !> Particle i's velocity and density half the step dt on from the half-step values uo, wo,
  !> rhoo with its current rates (the prediction, or the second kick), then p and c. A particle
  !> whose start-of-step position (xo, zo) lies in a driven nozzle moves rigidly with the plug
  !> instead: r = r^n + dt u_plug, u = u_plug (its density still follows continuity).
  subroutine half_kick(prm, st, i, dt)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer, intent(in) :: i
    real(rp), intent(in) :: dt
    real(rp) :: dt2
    dt2 = 0.5_rp * dt
    st%u(i) = st%uo(i) + dt2 * (st%ax(i) + prm%gravity%gx)
    st%w(i) = st%wo(i) + dt2 * (st%az(i) + prm%gravity%gz)
    st%rho(i) = st%rhoo(i) + dt2 * st%ar(i)
    if (prm%nozzle%u > 0.0_rp) then
      if (in_driven_nozzle(prm, st%xo(i), st%zo(i))) call plug_step(prm, st, i, dt, dt)
    end if
    call eos_one(prm, st, i)
  end subroutine half_kick

end module leapfrog
