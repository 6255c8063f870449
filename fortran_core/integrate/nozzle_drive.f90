!> The driven nozzle of sphjet's jet cases (cases/jet/README.md): the fluid that fills the
!> nozzle is a plug pushed out of the orifice at the jet speed u0. A fluid particle is in the
!> plug while its position lies upstream of the orifice line and within the plug's half-width
!> of the axis:
!>   s = (r - r0) . e < 0   and   |(r - r0) x e| <= half_width,
!> r0 the orifice centre, e the unit jet axis (flow direction). The test has no memory: fluid
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
  use sphjet_kinds, only: rp
  use sphjet_types, only: sph_params_t, state_t
  implicit none
  private
  public :: in_driven_nozzle, plug_step

contains

  pure logical function in_driven_nozzle(prm, x, z)
    type(sph_params_t), intent(in) :: prm
    real(rp), intent(in) :: x, z
    real(rp) :: rx, rz
    rx = x - prm%nozzle%x0
    rz = z - prm%nozzle%z0
    in_driven_nozzle = rx * prm%nozzle%ex + rz * prm%nozzle%ez < 0.0_rp .and. &
                       abs(rx * prm%nozzle%ez - rz * prm%nozzle%ex) <= prm%nozzle%half_width
  end function in_driven_nozzle

  !> A fluid particle whose start-of-step position lies in a driven nozzle (in_driven_nozzle),
  !> after the predictor-corrector's half_steps (or the leapfrog's kicks, with its whole step as
  !> dt2): it moves with the plug velocity instead, r = r^n + dt2 u_plug, u = u_plug (and
  !> u^n := u_plug, so that the corrector's extrapolation keeps u_plug); its density still
  !> follows continuity. u_plug is the plug speed along the axis, or with a parabolic profile
  !> the profile's speed at the particle's start-of-step distance from the axis (and then the
  !> density is profile_rho).
  !> With nozzle%release = 1 a particle that the plug carries past the orifice line turns free
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
    if (prm%nozzle%release == 1 .and. speed > 0.0_rp) then
      s_end = (st%xo(i) - prm%nozzle%x0) * prm%nozzle%ex + (st%zo(i) - prm%nozzle%z0) * prm%nozzle%ez &
              + t_end * speed
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

end module nozzle_drive
