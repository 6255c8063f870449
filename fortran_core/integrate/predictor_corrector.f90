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
!> A driven nozzle (sphjet's jets, nozzle_drive) moves the fluid inside it as a rigid plug
!> (nozzle_drive's plug_step).
module predictor_corrector
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use sphjet_kinds, only: rp, ip, i8, KIND_MOVING_BOUNDARY, BC_DYNAMIC, BC_REPULSIVE, &
                          SPH_OK
  use sphjet_types, only: sph_params_t, state_t, sph_step_info_t
  use sphjet_kernels, only: kernel_t
  use sorted_state, only: sorted_t, thread_lists
  use omp_team, only: team_work_t, in_team, one_thread, set_open_team
  use rates, only: compute_rates, rates_keep_pairs
  use time_step, only: cfl_scan_t, cfl_add, cfl_merge, cfl_time_step, capped_step
  use eos_tait, only: tait_pressure, tait_sound_speed
  use fluid_update, only: update_eos, moving_fluid, moves
  use state_checks, only: check_domain, fold_into_domain, reflect_at_axis
  use nozzle_drive, only: in_driven_nozzle, plug_step
  !$ use omp_lib, only: omp_get_thread_num, omp_get_num_threads
  implicit none
  private
  public :: pc_step

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
    dbc = prm%boundary%model == BC_DYNAMIC
    vmax_p = 0.0_rp
    vmax_c = 0.0_rp
    dt_p = dt
    dt_c = dt
    ! The gate's speed in the next step (it moves from t_start on), for the step bound.
    vgate = 0.0_rp
    if (st%nb > 0 .and. info%time + dt >= prm%boundary%gate_t_start) &
      vgate = sqrt(prm%boundary%gate_vx**2 + prm%boundary%gate_vz**2)

    ! The DBC density update of this step (boundary particles, every dbc_period steps)
    dbc_now = .false.
    if (dbc) then
      info%dbc_counter = info%dbc_counter + 1
      if (mod(info%dbc_counter, int(max(prm%boundary%dbc_period, 1), i8)) == 0) then
        dbc_now = .true.
        info%dbc_counter = 0
      end if
    end if

    ! Runs on several threads whose rates sweep keeps no pairs (rates_keep_pairs: planar,
    ! without surface tension or density diffusion) and not periodic: both stages in one
    ! parallel region, whose threads run the particle loops of the gather, the sweeps, the
    ! scatter and the integrator as its orphaned worksharing loops (omp_team.f90, in_team),
    ! so that a step has the barriers those loops need and no more (libgomp's passive waits
    ! make each barrier a futex sleep and wake-up).
    if (.not. one_thread() .and. .not. rates_keep_pairs(prm) .and. prm%geometry%periodic_z == 0) then
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
    if (prm%time_step%variable_dt /= 0) then
      call cfl_time_step(prm, work%scan(PREDICT), vmax_p, vgate, dtf, dtcv, dt_p)
      call cfl_time_step(prm, work%scan(CORRECT), vmax, vgate, dtf, dtcv, dt_c)
      info%dt_f = dtf
      info%dt_cv = dtcv
      info%dt_new = dt_c
    end if

    call move_gate(prm, st, info%time, dt)
    call reflect_at_axis(prm, st)    ! the corrector can carry a ring across the axis
    call fold_into_domain(prm, st)   ! periodic z

    info%visc_dt = vmax
    info%dt_next = merge(capped_step(prm, min(dt_p, dt_c)), dt, prm%time_step%variable_dt /= 0)
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
    ! Start-of-step values kept, and the fluid's half step, with one barrier at the end:
    ! each thread makes every pass over its own block of particles (step_loops), and with
    ! OpenMP's passive waits each barrier costs a thread wake-up, a large share of a small
    ! case's step.
    call in_team(work, PREDICT)
    if (dbc_now) then
      !$omp single
      do i = 1, st%nb
        st%rho(i) = max(st%rhoo(i) + work%dt2 * st%ar(i), prm%eos%rho0)
      end do
      call update_eos(prm, st, 1, st%nb)
      !$omp end single
    end if

    ! ---- corrector ----
    call reflect_at_axis(prm, st)   ! a ring that crossed the axis in the half step
    call compute_rates(prm, kern, st, s, vmax_c)
    ! The corrector's half step, phi^{n+1} = 2 phi^{n+1/2} - phi^n, and the EoS of every
    ! non-boundary particle, in one pass (one barrier instead of three; the EoS once, of the
    ! final density: the half step's p and c would be overwritten unread).
    call in_team(work, CORRECT)
    if (dbc_now) then
      !$omp single
      do i = 1, st%nb
        st%rho(i) = max(st%rhoo(i) + work%dt2 * st%ar(i), prm%eos%rho0)
        st%rho(i) = max(2.0_rp * st%rho(i) - st%rhoo(i), prm%eos%rho0)
      end do
      call update_eos(prm, st, 1, st%nb)
      !$omp end single
    end if
  end subroutine pc_stages

  !> The predictor's loops (start-of-step values kept, the fluid's half step and EoS) or the
  !> corrector's (half step, extrapolation, EoS of every non-boundary particle), each thread
  !> of the team over its own block of the particles (every thread calls it), or one thread
  !> over all.
  subroutine step_loops(self, which)
    class(step_work_t), intent(inout) :: self
    integer, intent(in) :: which
    integer :: j, j0, j1, me, nt
    type(cfl_scan_t) :: mine   ! this thread's share of the time-step scan
    me = 0
    nt = 1
    !$ me = omp_get_thread_num()
    !$ nt = omp_get_num_threads()
    associate (prm => self%prm, st => self%st, dt2 => self%dt2)
      ! this thread's block of the particles, the same in every pass below, so that each
      ! particle's steps keep their order without a barrier between the passes
      if (which == PREDICT) then
        call block_of(1, st%n, me, nt, j0, j1)
        do j = j0, j1
          st%xo(j) = st%x(j)
          st%zo(j) = st%z(j)
          st%uo(j) = st%u(j)
          st%wo(j) = st%w(j)
          st%rhoo(j) = st%rho(j)
        end do
        j0 = max(j0, st%nb + 1)
      else
        call block_of(st%nb + 1, st%n, me, nt, j0, j1)
      end if
      do j = j0, j1   ! the rates and c of the stage, before the update
        if (moving_fluid(st, j)) call cfl_add(mine, st, j)
      end do
      if (j1 >= j0) then
        call half_steps(j1 - j0 + 1, st%active(j0:j1), st%kind(j0:j1), dt2, &
                        prm%gravity%gx, prm%gravity%gz, &
                        st%rhoo(j0:j1), st%ar(j0:j1), st%xo(j0:j1), st%zo(j0:j1), &
                        st%uo(j0:j1), st%wo(j0:j1), st%xsph_u(j0:j1), st%xsph_w(j0:j1), &
                        st%ax(j0:j1), st%az(j0:j1), st%rho(j0:j1), st%x(j0:j1), &
                        st%z(j0:j1), st%u(j0:j1), st%w(j0:j1))
        if (prm%nozzle%u > 0.0_rp) then
          do j = j0, j1
            if (moving_fluid(st, j)) then
              if (in_driven_nozzle(prm, st%xo(j), st%zo(j))) call plug_step(prm, st, j, dt2, merge(2.0_rp * dt2, dt2, which == CORRECT))
            end if
          end do
        end if
        call stage_ends(which == CORRECT, j1 - j0 + 1, st%active(j0:j1), st%kind(j0:j1), &
                        prm%eos%rho0, prm%eos%b, prm%eos%gamma, prm%eos%c0, st%rhoo(j0:j1), st%xo(j0:j1), &
                        st%zo(j0:j1), st%uo(j0:j1), st%wo(j0:j1), st%rho(j0:j1), &
                        st%x(j0:j1), st%z(j0:j1), st%u(j0:j1), st%w(j0:j1), st%p(j0:j1), &
                        st%c(j0:j1))
      end if
      !$omp critical (step_cfl_scan)
      call cfl_merge(self%scan(which), mine)
      !$omp end critical (step_cfl_scan)
      ! the corrector: no barrier, what follows (the DBC update of particles 1..nb, pc_stages)
      ! reads nothing this loop writes, and the region ends with one
      if (which == PREDICT) then
        !$omp barrier
      end if
    end associate
  end subroutine step_loops

  !> Block me (0-based) of nt contiguous blocks of i0..i1 (the first ones one longer).
  pure subroutine block_of(i0, i1, me, nt, j0, j1)
    integer, intent(in) :: i0, i1, me, nt
    integer, intent(out) :: j0, j1
    integer :: n, q, r
    n = max(i1 - i0 + 1, 0)
    q = n / nt
    r = mod(n, nt)
    j0 = i0 + me * q + min(me, r)
    j1 = j0 + q - 1 + merge(1, 0, me < r)
  end subroutine block_of

  !> Half step of the moving fluid particles (active, fluid) of a block from their
  !> start-of-step values with the current rates: rho = rho^n + dt2 drho/dt, r = r^n + dt2 (u
  !> + XSPH), u = u^n + dt2 (a + g). Arrays, not the state's pointers, so that the compiler
  !> knows they do not overlap and vectorises the loop. A particle in a driven nozzle is moved
  !> again by plug_step afterwards.
  pure subroutine half_steps(n, act, kind, dt2, gx, gz, rhoo, ar, xo, zo, uo, wo, xu, xw, &
                             ax, az, rho, x, z, u, w)
    integer, intent(in) :: n
    integer(ip), intent(in) :: act(n), kind(n)
    real(rp), intent(in) :: dt2, gx, gz
    real(rp), intent(in) :: rhoo(n), ar(n), xo(n), zo(n), uo(n), wo(n), xu(n), xw(n), ax(n), az(n)
    real(rp), intent(inout) :: rho(n), x(n), z(n), u(n), w(n)
    integer :: k
    do k = 1, n
      if (moves(act(k), kind(k))) then
        rho(k) = rhoo(k) + dt2 * ar(k)
        x(k) = xo(k) + dt2 * (u(k) + xu(k))
        z(k) = zo(k) + dt2 * (w(k) + xw(k))
        u(k) = uo(k) + dt2 * (ax(k) + gx)
        w(k) = wo(k) + dt2 * (az(k) + gz)
      end if
    end do
  end subroutine half_steps

  !> The end of a stage for a block: the predictor's EoS of the moving fluid, or the
  !> corrector's phi^{n+1} = 2 phi^{n+1/2} - phi^n of the moving fluid and the EoS of every
  !> particle of the block (its final density).
  pure subroutine stage_ends(correct, n, act, kind, rho0, b, gamma, c0, rhoo, xo, zo, uo, wo, &
                             rho, x, z, u, w, p, c)
    logical, intent(in) :: correct
    integer, intent(in) :: n
    integer(ip), intent(in) :: act(n), kind(n)
    real(rp), intent(in) :: rho0, b, gamma, c0, rhoo(n), xo(n), zo(n), uo(n), wo(n)
    real(rp), intent(inout) :: rho(n), x(n), z(n), u(n), w(n), p(n), c(n)
    integer :: k
    logical :: moving
    do k = 1, n
      moving = moves(act(k), kind(k))
      if (correct .and. moving) then
        rho(k) = 2.0_rp * rho(k) - rhoo(k)
        x(k) = 2.0_rp * x(k) - xo(k)
        z(k) = 2.0_rp * z(k) - zo(k)
        u(k) = 2.0_rp * u(k) - uo(k)
        w(k) = 2.0_rp * w(k) - wo(k)
      end if
      if (correct .or. moving) then
        p(k) = tait_pressure(rho(k), rho0, b, gamma)
        c(k) = tait_sound_speed(rho(k), rho0, c0)
      end if
    end do
  end subroutine stage_ends

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
    if (time < prm%boundary%gate_t_start) return
    rigid = prm%boundary%model == BC_REPULSIVE
    dzm = prm%boundary%gate_vz * dt
    if (rigid .and. dzm > 0.0_rp) then
      zlow = huge(1.0_rp)
      do i = 1, st%nb
        if (st%kind(i) == KIND_MOVING_BOUNDARY) zlow = min(zlow, st%z(i))
      end do
      dzm = min(dzm, max(prm%boundary%gate_z_cap - zlow, 0.0_rp))
    end if
    do i = 1, st%nb
      if (st%kind(i) /= KIND_MOVING_BOUNDARY) cycle
      st%x(i) = st%x(i) + prm%boundary%gate_vx * dt
      st%u(i) = prm%boundary%gate_vx
      if (rigid) then
        st%z(i) = st%z(i) + dzm
        st%w(i) = dzm / dt
      else
        st%z(i) = min(st%z(i) + dzm, prm%boundary%gate_z_cap)
        st%w(i) = prm%boundary%gate_vz
      end if
    end do
  end subroutine move_gate

end module predictor_corrector
