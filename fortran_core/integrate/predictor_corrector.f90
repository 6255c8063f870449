!> Predictor-corrector time integration (Monaghan 1989) as SPHysics 2D performs it:
!>   predictor: rates at t^n; phi^{n+1/2} = phi^n + dt/2 dphi^n/dt
!>   corrector: rates at t^{n+1/2}; phi^{n+1/2} = phi^n + dt/2 dphi^{n+1/2}/dt;
!>              phi^{n+1} = 2 phi^{n+1/2} - phi^n
!> for positions (moved with velocity + XSPH correction), velocities and densities of the
!> fluid; pressure and sound speed follow from the EoS after each density update. Dynamic
!> boundary particles update their density every dbc_period steps and never drop below rho0.
!> The step for the next call is min of the CFL steps of both stages; note that SPHysics
!> then advances its clock by that new step, not by the one just taken (this fork advances
!> by the step taken; the driver keeps the legacy clock too, for comparisons).
!> A driven nozzle (sphjet's jets, nozzle_drive) moves the fluid inside it as a rigid plug.
module predictor_corrector
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use sphjet_kinds, only: rp, ip, i8, KIND_FLUID, KIND_MOVING_BOUNDARY, BC_DYNAMIC, BC_REPULSIVE, &
                          SPH_OK, GEOM_AXISYMMETRIC
  use sphjet_types, only: sph_params_t, state_t, sph_step_info_t
  use sphjet_kernels, only: kernel_t
  use sorted_state, only: sorted_t, team_work_t, in_team, one_thread, set_open_team, thread_lists
  use rates, only: compute_rates
  use time_step, only: cfl_scan_t, cfl_add, cfl_merge, cfl_time_step
  use eos_tait, only: tait_pressure, tait_sound_speed
  use state_checks, only: check_domain, fold_into_domain
  use nozzle_drive, only: in_driven_nozzle
  implicit none
  private
  public :: pc_step, update_eos

  !> The particle loops of a step (in_team): which = PREDICT or CORRECT. They also make the
  !> time step's scan of the stage's rates (time_step.f90), into scan(which).
  integer, parameter :: PREDICT = 1, CORRECT = 2
  type, extends(team_work_t) :: step_work_t
    type(sph_params_t) :: prm
    type(state_t), pointer :: st => null()
    real(rp) :: dt2 = 0.0_rp
    type(cfl_scan_t) :: scan(PREDICT:CORRECT)
  contains
    procedure :: run => step_loops
  end type step_work_t

contains

  !> p and c from rho for particles first..last.
  subroutine update_eos(prm, st, first, last)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer, intent(in) :: first, last
    integer :: i
    !$omp parallel do schedule(static)
    do i = first, last
      call eos_one(prm, st, i)
    end do
    !$omp end parallel do
  end subroutine update_eos

  !> p and c of particle i from its density.
  subroutine eos_one(prm, st, i)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer, intent(in) :: i
    st%p(i) = tait_pressure(st%rho(i), prm%rho0, prm%b, prm%gamma)
    st%c(i) = tait_sound_speed(st%rho(i), prm%rho0, prm%c0)
  end subroutine eos_one

  !> Whether particle i is fluid still in the domain (the particles the integrator advances).
  pure logical function moving_fluid(st, i)
    type(state_t), intent(in) :: st
    integer, intent(in) :: i
    moving_fluid = st%active(i) /= 0 .and. st%kind(i) == KIND_FLUID
  end function moving_fluid

  subroutine pc_step(prm, kern, st, s, info, status)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout), target :: st
    type(sorted_t), intent(inout) :: s
    type(sph_step_info_t), intent(inout) :: info
    integer(ip), intent(out) :: status
    real(rp) :: dt, dt2, vmax, vmax_p, vmax_c, dt_p, dt_c, vgate, dtf, dtcv
    logical :: dbc, dbc_now
    type(step_work_t) :: work

    dt = info%dt
    dt2 = 0.5_rp * dt
    work%prm = prm
    work%st => st
    work%dt2 = dt2
    dbc = prm%boundary == BC_DYNAMIC
    vmax_p = 0.0_rp
    vmax_c = 0.0_rp
    dt_p = dt
    dt_c = dt
    ! The gate's speed in the next step (it moves from t_start on), for the step bound.
    vgate = 0.0_rp
    if (st%nb > 0 .and. info%time + dt >= prm%gate_t_start) vgate = sqrt(prm%gate_vx**2 + prm%gate_vz**2)

    ! The DBC density update of this step (boundary particles, every dbc_period steps)
    dbc_now = .false.
    if (dbc) then
      info%dbc_counter = info%dbc_counter + 1
      if (mod(info%dbc_counter, int(max(prm%dbc_period, 1), i8)) == 0) then
        dbc_now = .true.
        info%dbc_counter = 0
      end if
    end if

    ! Planar runs without surface tension on several threads: both stages in one parallel
    ! region, whose threads run the particle loops of the gather, the sweeps, the scatter
    ! and the integrator as its orphaned worksharing loops (sorted_state.f90, in_team), so
    ! that a step has the barriers those loops need and no more (libgomp's passive waits
    ! make each barrier a futex sleep and wake-up).
    if (.not. one_thread() .and. prm%geometry /= GEOM_AXISYMMETRIC .and. prm%periodic_z == 0 &
        .and. .not. prm%sigma > 0.0_rp) then
      call thread_lists(s)
      !$omp parallel
      call set_open_team(.true.)
      call pc_stages(prm, kern, st, s, work, dbc_now, vmax_p, vmax_c)
      call set_open_team(.false.)
      !$omp end parallel
    else
      call pc_stages(prm, kern, st, s, work, dbc_now, vmax_p, vmax_c)
    end if

    ! the next step from each stage's rates; the corrector's viscous bound takes the max of
    ! both stages' pairs
    vmax = max(vmax_p, vmax_c)
    if (prm%variable_dt /= 0) then
      call cfl_time_step(prm, work%scan(PREDICT), vmax_p, vgate, dtf, dtcv, dt_p)
      call cfl_time_step(prm, work%scan(CORRECT), vmax, vgate, dtf, dtcv, dt_c)
      info%dt_f = dtf
      info%dt_cv = dtcv
      info%dt_new = dt_c
    end if

    call move_gate(prm, st, info%time, dt)
    call fold_into_domain(prm, st)   ! axis reflection, periodic z (nothing in planar runs)

    info%visc_dt = vmax
    info%dt_next = merge(min(dt_p, dt_c), dt, prm%variable_dt /= 0)
    call check_domain(prm, st, info%n_removed, info%bad_particle, status)
    ! A removal changes the active set: the next gather lists the pairs again, from the
    ! positions then (list_x = NaN, which a checkpoint keeps, so a resumed run does the same).
    if (info%n_removed > 0) then
      s%built = .false.
      if (associated(st%list_x)) st%list_x = ieee_value(1.0_rp, ieee_quiet_nan)
      if (associated(st%list_z)) st%list_z = ieee_value(1.0_rp, ieee_quiet_nan)
    end if
    info%bad_cause = status
    if (status /= SPH_OK) return

  end subroutine pc_step


  !> The predictor and corrector stages of pc_step, called by every thread of a parallel
  !> region or by this thread alone (then the `single` sections run here and every set of
  !> loops opens its own region). What the stages find goes to the caller's (shared)
  !> variables: each stage's max of the viscous pair term (vmax_p, vmax_c) and, in work,
  !> its time-step scan.
  subroutine pc_stages(prm, kern, st, s, work, dbc_now, vmax_p, vmax_c)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(state_t), intent(inout), target :: st
    type(sorted_t), intent(inout) :: s
    type(step_work_t), intent(inout) :: work
    logical, intent(in) :: dbc_now
    real(rp), intent(inout) :: vmax_p, vmax_c
    integer :: i

    ! ---- predictor ----
    call compute_rates(prm, kern, st, s, vmax_p)
    ! Start-of-step values kept, and the fluid's half step, in one pass: every parallel loop
    ! ends in a barrier, and with OpenMP's passive wait policy (the default, main.cpp) each
    ! barrier costs a thread wake-up, a large share of a small case's step.
    call in_team(work, PREDICT)
    if (dbc_now) then
      !$omp single
      do i = 1, st%nb
        st%rho(i) = max(st%rhoo(i) + work%dt2 * st%ar(i), prm%rho0)
      end do
      call update_eos(prm, st, 1, st%nb)
      !$omp end single
    end if

    ! ---- corrector ----
    call compute_rates(prm, kern, st, s, vmax_c)
    ! The corrector's half step, phi^{n+1} = 2 phi^{n+1/2} - phi^n, and the EoS of every
    ! non-boundary particle, in one pass (one barrier instead of three; the EoS once, of the
    ! final density: the half step's p and c would be overwritten unread).
    call in_team(work, CORRECT)
    if (dbc_now) then
      !$omp single
      do i = 1, st%nb
        st%rho(i) = max(st%rhoo(i) + work%dt2 * st%ar(i), prm%rho0)
        st%rho(i) = max(2.0_rp * st%rho(i) - st%rhoo(i), prm%rho0)
      end do
      call update_eos(prm, st, 1, st%nb)
      !$omp end single
    end if
  end subroutine pc_stages

  !> The predictor's loop (start-of-step values kept, the fluid's half step and EoS) or the
  !> corrector's (half step, extrapolation, EoS of every non-boundary particle): orphaned
  !> worksharing loops.
  subroutine step_loops(self, which)
    class(step_work_t), intent(inout) :: self
    integer, intent(in) :: which
    integer :: j
    type(cfl_scan_t) :: mine   ! this thread's share of the time-step scan
    associate (prm => self%prm, st => self%st, dt2 => self%dt2)
      if (which == PREDICT) then
        !$omp do schedule(static)
        do j = 1, st%n
          st%xo(j) = st%x(j)
          st%zo(j) = st%z(j)
          st%uo(j) = st%u(j)
          st%wo(j) = st%w(j)
          st%rhoo(j) = st%rho(j)
          if (j > st%nb) then
            if (moving_fluid(st, j)) then
              call cfl_add(mine, st, j)   ! the rates and c of the stage, before the update
              call half_step(prm, st, j, dt2)
              call eos_one(prm, st, j)
            end if
          end if
        end do
        !$omp end do nowait
        !$omp critical (step_cfl_scan)
        call cfl_merge(self%scan(which), mine)
        !$omp end critical (step_cfl_scan)
        !$omp barrier
      else
        !$omp do schedule(static)
        do j = st%nb + 1, st%n
          if (moving_fluid(st, j)) then
            call cfl_add(mine, st, j)
            call half_step(prm, st, j, dt2)
            st%rho(j) = 2.0_rp * st%rho(j) - st%rhoo(j)
            st%x(j) = 2.0_rp * st%x(j) - st%xo(j)
            st%z(j) = 2.0_rp * st%z(j) - st%zo(j)
            st%u(j) = 2.0_rp * st%u(j) - st%uo(j)
            st%w(j) = 2.0_rp * st%w(j) - st%wo(j)
          end if
          call eos_one(prm, st, j)
        end do
        ! no barrier: what follows (the DBC update of particles 1..nb, pc_stages) reads
        ! nothing this loop writes, and the region ends with one
        !$omp end do nowait
        !$omp critical (step_cfl_scan)
        call cfl_merge(self%scan(which), mine)
        !$omp end critical (step_cfl_scan)
      end if
    end associate
  end subroutine step_loops

  !> Moving boundary particles (a legacy gate), moved after the corrector as SPHysics'
  !> movingGate does: from t >= gate_t_start (t = this step's start, sphjet's clock) by
  !> (gate_vx, gate_vz) dt (the step taken; legacy moves by the next step's dt), velocity set
  !> to the gate's (it enters the pair forces); at rest before. Dynamic boundaries, as legacy:
  !> each particle's z is capped at gate_z_cap (a lifted gate gathers there). Repulsive walls
  !> (sphjet only): the line moves rigidly and stops, w = 0, when its lowest particle reaches
  !> the cap, so that its particles never coincide (their normals come from their neighbours).
  subroutine move_gate(prm, st, time, dt)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    real(rp), intent(in) :: time, dt
    integer :: i
    logical :: rigid
    real(rp) :: dzm, zlow
    if (time < prm%gate_t_start) return
    rigid = prm%boundary == BC_REPULSIVE
    dzm = prm%gate_vz * dt
    if (rigid .and. dzm > 0.0_rp) then
      zlow = huge(1.0_rp)
      do i = 1, st%nb
        if (st%kind(i) == KIND_MOVING_BOUNDARY) zlow = min(zlow, st%z(i))
      end do
      dzm = min(dzm, max(prm%gate_z_cap - zlow, 0.0_rp))
    end if
    do i = 1, st%nb
      if (st%kind(i) /= KIND_MOVING_BOUNDARY) cycle
      st%x(i) = st%x(i) + prm%gate_vx * dt
      st%u(i) = prm%gate_vx
      if (rigid) then
        st%z(i) = st%z(i) + dzm
        st%w(i) = dzm / dt
      else
        st%z(i) = min(st%z(i) + dzm, prm%gate_z_cap)
        st%w(i) = prm%gate_vz
      end if
    end do
  end subroutine move_gate

  !> Half step of fluid particle i from its start-of-step values with the current rates:
  !> rho = rho^n + dt2 drho/dt, r = r^n + dt2 (u + XSPH), u = u^n + dt2 (a + g).
  !> A fluid particle whose start-of-step position lies in a driven nozzle (nozzle_drive)
  !> moves rigidly with the plug velocity instead: r = r^n + dt2 u_plug, u = u_plug (and
  !> u^n := u_plug, so that the corrector's extrapolation keeps u_plug); its density still
  !> follows continuity.
  subroutine half_step(prm, st, i, dt2)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer, intent(in) :: i
    real(rp), intent(in) :: dt2
    st%rho(i) = st%rhoo(i) + dt2 * st%ar(i)
    if (prm%drive_u > 0.0_rp) then
      if (in_driven_nozzle(prm, st%xo(i), st%zo(i))) then
        st%u(i) = prm%drive_u * prm%drive_ex
        st%w(i) = prm%drive_u * prm%drive_ez
        st%x(i) = st%xo(i) + dt2 * st%u(i)
        st%z(i) = st%zo(i) + dt2 * st%w(i)
        ! The corrector's u = 2 u^{n+1/2} - u^n must give the plug's velocity also for a
        ! particle that entered the plug with another one.
        st%uo(i) = st%u(i)
        st%wo(i) = st%w(i)
        return
      end if
    end if
    st%x(i) = st%xo(i) + dt2 * (st%u(i) + st%xsph_u(i))
    st%z(i) = st%zo(i) + dt2 * (st%w(i) + st%xsph_w(i))
    st%u(i) = st%uo(i) + dt2 * (st%ax(i) + prm%gx)
    st%w(i) = st%wo(i) + dt2 * (st%az(i) + prm%gz)
  end subroutine half_step

end module predictor_corrector
