!> The driven nozzle of sphjet's jet cases (cases/jet/README.md): the fluid that fills the
!> nozzle is a plug pushed out of the orifice at the jet speed u0. A fluid particle is in the
!> plug while its position lies upstream of the orifice line and within the plug's half-width
!> of the axis (physics/nozzle_geometry.f90, in_driven_nozzle). The test has no memory: fluid
!> that comes back upstream into that strip is driven again (with the plug's velocity, see
!> plug_step below); keep other fluid regions out of it. With a parabolic exit profile
!> (profile_a > 0, a tube's fully developed laminar flow) the speed along the axis depends on
!> the distance l = |(r - r0) x e| from it, u k (1 - l^2 / a^2), a = profile_a, k = profile_k
!> chosen by the driver so that the lattice's flux is u's. Fluid farther out than the plug's
!> outer line (l > profile_lmax, fluid that spread at the lip) moves with that line: at zero speed
!> it would stay at the lip for good, a wall of its own. A profiled plug holds the density it was
!> built with (profile_rho): its lines slide past one another, and continuity over the sheared
!> lattice gave its pressure a standard deviation of 80 sigma/a (0.58 m/s round jet, d0/dx 10).
module nozzle_drive
  use sphjet_kinds, only: rp, NOZZLE_RELEASE_LANDED
  use sphjet_types, only: sph_params_t, state_t
  use fluid_update, only: moving_fluid
  use nozzle_geometry, only: past_orifice, in_driven_nozzle
  implicit none
  private
  public :: in_driven_nozzle, plug_step, landed_step

  !> How far past the orifice line a landed step carries the plug's leading row, in parts of the
  !> step asked (landed_step): enough that round-off of the positions (1e-16 of the box) cannot
  !> leave the row upstream, a time past the line ten million times shorter than the step.
  real(rp), parameter :: LAND_PAST = 1.0e-7_rp
  !> A landed step may exceed the step asked by this part of it, so that a time to the crossing
  !> of n steps and round-off (or LAND_PAST) is n steps, not n + 1.
  real(rp), parameter :: LAND_SLACK = 1.0e-6_rp

contains

  !> A fluid particle whose start-of-step position lies in a driven nozzle (in_driven_nozzle),
  !> after the predictor-corrector's half_steps (or the leapfrog's kicks, with its whole step as
  !> dt2): it moves with the plug velocity instead, r = r^n + dt2 u_plug, u = u_plug (and
  !> u^n := u_plug, so that the corrector's extrapolation keeps u_plug); its density still
  !> follows continuity. u_plug is the plug speed along the axis, or with a parabolic profile
  !> the profile's speed at the particle's start-of-step distance from the axis (and then the
  !> density is profile_rho).
  !> With nozzle%release = 1 or 2 a particle that the plug carries past the orifice line turns free
  !> there: t_end is the time from the step's start to the state these values stand for (the
  !> leapfrog's dt, the predictor's dt/2, the corrector's dt, which its extrapolation reaches),
  !> t_out = s_end / speed of it was spent past the line (s_end the particle's distance past it
  !> at t_end, speed the plug's there), and u = u_plug + t_out (a + g) with the current rates.
  !> Otherwise every row leaves with u_plug from a step that ends anywhere up to dt past its
  !> crossing: behind a jet that accelerates (gravity), rows whose velocities lag by a jitter
  !> of up to dt a. Its position keeps r^n + dt2 u_plug: the free motion's t_out^2 a / 2 is a
  !> millionth of a spacing at the jets' steps.
  subroutine plug_step(prm, st, i, dt2, t_end)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer, intent(in) :: i
    real(rp), intent(in) :: dt2, t_end
    real(rp) :: speed, l, s_end, t_out
    speed = prm%nozzle%u
    if (prm%nozzle%profile_a > 0.0_rp) then
      l = min(abs((st%xo(i) - prm%nozzle%x0) * prm%nozzle%ez - (st%zo(i) - prm%nozzle%z0) * prm%nozzle%ex), &
              prm%nozzle%profile_lmax) / prm%nozzle%profile_a
      speed = speed * prm%nozzle%profile_k * (1.0_rp - l * l)
      st%rho(i) = prm%nozzle%profile_rho
      st%rhoo(i) = prm%nozzle%profile_rho   ! as uo below: the corrector's 2 rho - rho^n keeps it
    end if
    st%u(i) = speed * prm%nozzle%ex
    st%w(i) = speed * prm%nozzle%ez
    st%x(i) = st%xo(i) + dt2 * st%u(i)
    st%z(i) = st%zo(i) + dt2 * st%w(i)
    if (prm%nozzle%release >= 1 .and. speed > 0.0_rp) then
      s_end = past_orifice(prm, st%xo(i), st%zo(i)) + t_end * speed
      if (s_end > 0.0_rp) then
        t_out = min(s_end / speed, t_end)
        st%u(i) = st%u(i) + t_out * (st%ax(i) + prm%gravity%gx)
        st%w(i) = st%w(i) + t_out * (st%az(i) + prm%gravity%gz)
      end if
    end if
    ! The corrector's u = 2 u^{n+1/2} - u^n must give the plug's velocity also for a
    ! particle that entered the plug with another one.
    st%uo(i) = st%u(i)
    st%wo(i) = st%w(i)
  end subroutine plug_step

  !> nozzle%release = 2 (nozzle.release = "landed"): the step to take instead of dt, so that the
  !> plug's leading row (the driven particle nearest the orifice line) crosses the line at a step's
  !> end, LAND_PAST dt past it, and turns free there with no lag. The time to that crossing, r, is
  !> cut into n = ceiling(r / dt (1 - LAND_SLACK)) equal steps; each call takes the first of them,
  !> so the steps between two rows' crossings are equal while dt holds, and never longer than dt
  !> (but for LAND_SLACK). dt itself where nothing is driven or the profile is parabolic (its
  !> lines cross at different times). The plug speed is this step's (prm%nozzle%u), so a
  !> disturbed plug lands as well at the step that reaches the line.
  real(rp) function landed_step(prm, st, dt) result(dt_land)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(in) :: st
    real(rp), intent(in) :: dt
    real(rp) :: lead, r
    integer :: i
    dt_land = dt
    if (prm%nozzle%release /= NOZZLE_RELEASE_LANDED .or. .not. (prm%nozzle%u > 0.0_rp) &
        .or. prm%nozzle%profile_a > 0.0_rp) return
    lead = -huge(1.0_rp)
    !$omp parallel do schedule(static) reduction(max:lead)
    do i = 1, st%n
      if (.not. moving_fluid(st, i)) cycle
      if (.not. in_driven_nozzle(prm, st%x(i), st%z(i))) cycle
      lead = max(lead, past_orifice(prm, st%x(i), st%z(i)))
    end do
    !$omp end parallel do
    if (lead == -huge(1.0_rp)) return
    r = -lead / prm%nozzle%u + LAND_PAST * dt
    dt_land = r / real(max(1, ceiling(r / dt * (1.0_rp - LAND_SLACK))), rp)
  end function landed_step

end module nozzle_drive
