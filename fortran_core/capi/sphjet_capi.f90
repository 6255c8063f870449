!> The C interface of the core: thin bind(C) shims that check their arguments, bind the
!> arrays lent by C++ and call the internal routines. They never stop the program: every
!> failure is an integer status (SPH_* codes of sphjet_kinds, mirrored in sphjet_core.h).
module sphjet_capi
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_loc, &
                                         c_f_pointer, c_associated, c_null_ptr
  use omp_lib, only: omp_set_num_threads, omp_get_max_threads
  use sphjet_kinds, only: rp, ip, i8, SPH_OK, SPH_ERR_ARGUMENT, SPH_ERR_CAPACITY, &
                          SPH_ERR_DT_COLLAPSE, BC_REPULSIVE, BC_DYNAMIC, VISC_ARTIFICIAL, &
                          VISC_LAMINAR, FILTER_NONE, FILTER_MLS, KIND_FLUID, &
                          GEOM_PLANAR, GEOM_AXISYMMETRIC, AXIS_PAIR_SMOOTHED_RADIUS, &
                          AXIS_PAIR_RINGS, RINGS_CURVATURE_MEAN, RINGS_CURVATURE_OWN, &
                          CURV_NORMALS_ALL, CURV_NORMALS_BAND, CURVATURE_NORMALS, &
                          CURVATURE_SURFACE_FIT, INTEGRATOR_PC, INTEGRATOR_LEAPFROG
  use sphjet_types, only: sph_params_t, sph_arrays_t, sph_step_info_t, state_t, bind_state
  use sphjet_kernels, only: kernel_t, kernel_setup, kernel_eval, kernel_valid
  use sorted_state, only: sorted_t, R_AX, R_AZ
  use list_rebuild, only: gather_sorted
  use traversal, only: pair_list_t, build_row_pairs, PAIRS_ALL
  use rates, only: compute_rates
  use predictor_corrector, only: pc_step
  use fluid_update, only: update_eos
  use leapfrog, only: lf_step
  use nozzle_drive, only: landed_step
  use filter_loops, only: apply_density_filter
  use state_checks, only: check_finite, rings_to_split
  use repulsive_wall, only: wall_normal
  use eos_tait, only: tait_pressure, tait_sound_speed
  use surface_tension_loops, only: surface_tension_rates
  use surface_tension, only: ST_DELTA_PRESSURE, ST_DELTA_COLOUR, N_FIT, csf_fit_point, csf_fit_curvature
  implicit none
  private
  public :: sph_workspace_create, sph_workspace_destroy, sph_set_threads, sph_get_threads, &
            sph_threads_for, &
            sph_prepare, sph_step, sph_density_filter, sph_check_state, sph_compute_rates, &
            sph_kernel_eval, sph_surface_fit, sph_neighbour_pairs, sph_eos, &
            sph_surface_tension_fields

  !> A step or filter call uses at most one thread per this many particles: a step of a small
  !> case is not worth sharing (some ten parallel regions a step, whose passive wake-ups cost
  !> tens of microseconds each). Measured on 2 cores (Laplace disc, 2 threads against 1,
  !> alternated whole-process timings, with / without surface tension): 573 particles 1.01
  !> (not worth it), 856 particles 0.89 / 0.82, 1076 particles 0.83 / 0.74, 1321 particles
  !> 0.79 / 0.71. Results do not depend on the thread count, so this changes the speed only.
  integer, parameter :: PARTICLES_PER_THREAD = 400

  !> Scratch memory of the core, kept between calls (opaque to C++).
  type :: workspace_t
    type(sorted_t) :: sorted
  end type workspace_t

contains

  function sph_workspace_create() result(handle) bind(C, name="sph_workspace_create")
    type(c_ptr) :: handle
    type(workspace_t), pointer :: ws
    allocate(ws)
    handle = c_loc(ws)
  end function sph_workspace_create

  subroutine sph_workspace_destroy(handle) bind(C, name="sph_workspace_destroy")
    type(c_ptr), value :: handle
    type(workspace_t), pointer :: ws
    if (.not. c_associated(handle)) return
    call c_f_pointer(handle, ws)
    deallocate(ws)
  end subroutine sph_workspace_destroy

  subroutine sph_set_threads(n) bind(C, name="sph_set_threads")
    integer(c_int), value :: n
    if (n > 0) call omp_set_num_threads(n)
  end subroutine sph_set_threads

  function sph_get_threads() result(n) bind(C, name="sph_get_threads")
    integer(c_int) :: n
    n = omp_get_max_threads()
  end function sph_get_threads

  !> The threads a step or filter call of n particles runs on: the count set
  !> (sph_set_threads), at most one per PARTICLES_PER_THREAD particles, at least one.
  function sph_threads_for(n) result(nt) bind(C, name="sph_threads_for")
    integer(c_int), value :: n
    integer(c_int) :: nt
    nt = max(1, min(omp_get_max_threads(), n / PARTICLES_PER_THREAD))
  end function sph_threads_for

  !> Sets the threads of the next parallel regions to sph_threads_for(n); returns the count
  !> to restore afterwards.
  integer function share_threads(n) result(nt_caller)
    integer, intent(in) :: n
    nt_caller = omp_get_max_threads()
    call omp_set_num_threads(sph_threads_for(n))
  end function share_threads

  !> Checks the options and values every routine relies on.
  logical function params_ok(prm)
    type(sph_params_t), intent(in) :: prm
    params_ok = kernel_valid(prm%numerics%kernel) .and. prm%numerics%h > 0.0_rp &
      .and. prm%eos%rho0 > 0.0_rp &
      .and. prm%eos%b >= 0.0_rp .and. prm%eos%c0 >= 0.0_rp .and. prm%eos%gamma > 0.0_rp &
      .and. any(prm%boundary%model == [BC_REPULSIVE, BC_DYNAMIC]) &
      .and. any(prm%viscosity%model == [VISC_ARTIFICIAL, VISC_LAMINAR]) &
      .and. prm%numerics%density_filter >= FILTER_NONE .and. prm%numerics%density_filter <= FILTER_MLS &
      .and. prm%time_step%cfl > 0.0_rp .and. prm%surface_tension%sigma >= 0.0_rp &
      .and. any(prm%surface_tension%delta == [ST_DELTA_PRESSURE, ST_DELTA_COLOUR]) &
      .and. any(prm%geometry%kind == [GEOM_PLANAR, GEOM_AXISYMMETRIC]) &
      .and. any(prm%geometry%periodic_z == [0, 1]) &
      .and. any(prm%geometry%axis_pair == [AXIS_PAIR_SMOOTHED_RADIUS, AXIS_PAIR_RINGS]) &
      .and. any(prm%surface_tension%rings_curvature == [RINGS_CURVATURE_MEAN, RINGS_CURVATURE_OWN]) &
      .and. any(prm%surface_tension%curvature_normals == [CURV_NORMALS_ALL, CURV_NORMALS_BAND]) &
      .and. any(prm%surface_tension%curvature == [CURVATURE_NORMALS, CURVATURE_SURFACE_FIT]) &
      .and. prm%surface_tension%fit_points_min >= 0 &
      .and. prm%geometry%axis_m1 >= 0.0_rp .and. prm%numerics%density_diffusion >= 0.0_rp &
      .and. prm%numerics%bulk_viscosity >= 0.0_rp .and. prm%viscosity%artificial_alpha >= 0.0_rp &
      .and. prm%numerics%shifting >= 0.0_rp &
      .and. prm%nozzle%profile_a >= 0.0_rp .and. any(prm%nozzle%release == [0, 1, 2]) &
      .and. any(prm%viscosity%reconstruct == [0, 1]) &
      .and. any(prm%numerics%integrator == [INTEGRATOR_PC, INTEGRATOR_LEAPFROG])
    ! shifting's velocity is set by the surface tension's passes (surface_tension_loops.f90)
    if (prm%numerics%shifting > 0.0_rp) params_ok = params_ok .and. prm%surface_tension%sigma > 0.0_rp
    ! a parabolic exit profile: a centre speed, and an outer line inside the tube
    if (prm%nozzle%profile_a > 0.0_rp) params_ok = params_ok .and. prm%nozzle%profile_k > 0.0_rp &
      .and. prm%nozzle%profile_lmax >= 0.0_rp .and. prm%nozzle%profile_lmax < prm%nozzle%profile_a &
      .and. prm%nozzle%profile_rho > 0.0_rp
    ! a period must hold the images of both ends apart (two kernel supports)
    if (prm%geometry%periodic_z /= 0) params_ok = params_ok .and. &
      prm%domain%zmax - prm%domain%zmin > 4.0_rp * prm%numerics%h
    if (prm%boundary%model == BC_REPULSIVE) params_ok = params_ok .and. prm%boundary%h_swl > 0.0_rp &
      .and. prm%boundary%coef > 0.0_rp
  end function params_ok

  !> Sets pressure and sound speed from density (all particles) and, for repulsive walls,
  !> the wall normals from the wall links.
  function sph_prepare(prm, arr) result(status) bind(C, name="sph_prepare")
    type(sph_params_t), intent(in) :: prm
    type(sph_arrays_t), intent(in) :: arr
    integer(c_int) :: status
    type(state_t) :: st
    logical :: ok, repulsive
    integer :: i, ip_, in_
    status = SPH_ERR_ARGUMENT
    if (.not. params_ok(prm)) return
    repulsive = prm%boundary%model == BC_REPULSIVE
    call bind_state(arr, st, .false., repulsive, ok)
    if (.not. ok) return
    call update_eos(prm, st, 1, st%n)
    if (repulsive) then
      do i = 1, st%nb
        ip_ = st%wall_prev(i) + 1
        in_ = st%wall_next(i) + 1
        if (ip_ < 1 .or. ip_ > st%nb .or. in_ < 1 .or. in_ > st%nb) return
        if (ip_ == i .and. in_ == i) return
        call wall_normal(st%x(ip_), st%z(ip_), st%x(i), st%z(i), st%x(in_), st%z(in_), &
                         ip_ == i, in_ == i, prm%numerics%h, st%wall_nx(i), st%wall_nz(i), &
                         st%wall_dback(i), st%wall_dfwd(i))
      end do
    end if
    status = SPH_OK
  end function sph_prepare

  !> One step of numerics%integrator (the predictor-corrector or the leapfrog); info%dt is the
  !> step to take, and returns the step taken: shorter where nozzle%release = 2 lands the plug's
  !> leading row on the orifice line (nozzle_drive.f90, landed_step).
  function sph_step(ws_handle, prm, arr, info) result(status) bind(C, name="sph_step")
    type(c_ptr), value :: ws_handle
    type(sph_params_t), intent(in) :: prm
    type(sph_arrays_t), intent(in) :: arr
    type(sph_step_info_t), intent(inout) :: info
    integer(c_int) :: status
    type(workspace_t), pointer :: ws
    type(state_t) :: st
    type(kernel_t) :: kern
    logical :: ok
    integer :: nt
    real(rp) :: dt_asked
    status = SPH_ERR_ARGUMENT
    if (.not. c_associated(ws_handle)) return
    if (.not. params_ok(prm)) return
    if (.not. (info%dt > 0.0_rp)) return
    call bind_state(arr, st, .true., prm%boundary%model == BC_REPULSIVE, ok)
    if (.not. ok) return
    call c_f_pointer(ws_handle, ws)
    kern = kernel_setup(prm%numerics%kernel, prm%numerics%h)
    info%n_removed = 0
    info%bad_particle = -1
    info%bad_cause = SPH_OK
    nt = share_threads(st%n)
    dt_asked = info%dt
    info%dt = landed_step(prm, st, dt_asked)
    if (prm%numerics%integrator == INTEGRATOR_LEAPFROG) then
      call lf_step(prm, kern, st, ws%sorted, info, status)
    else
      call pc_step(prm, kern, st, ws%sorted, info, status)
    end if
    call omp_set_num_threads(nt)
    ! a fixed step keeps its size: only the steps that land the plug's rows are shorter
    if (prm%time_step%variable_dt == 0) info%dt_next = dt_asked
    if (status /= SPH_OK) return
    if (prm%time_step%variable_dt /= 0 .and. info%dt_next < prm%time_step%dt_min) then
      status = SPH_ERR_DT_COLLAPSE
      info%bad_cause = status
    end if
  end function sph_step

  function sph_density_filter(ws_handle, prm, arr, n_singular) result(status) &
      bind(C, name="sph_density_filter")
    type(c_ptr), value :: ws_handle
    type(sph_params_t), intent(in) :: prm
    type(sph_arrays_t), intent(in) :: arr
    integer(c_int64_t), intent(out) :: n_singular
    integer(c_int) :: status
    type(workspace_t), pointer :: ws
    type(state_t) :: st
    logical :: ok
    integer :: ns, nt
    status = SPH_ERR_ARGUMENT
    n_singular = 0
    if (.not. c_associated(ws_handle)) return
    if (.not. params_ok(prm)) return
    call bind_state(arr, st, .false., .false., ok)
    if (.not. ok) return
    call c_f_pointer(ws_handle, ws)
    nt = share_threads(st%n)
    call apply_density_filter(prm, kernel_setup(prm%numerics%kernel, prm%numerics%h), st, ws%sorted, ns)
    call omp_set_num_threads(nt)
    n_singular = ns
    status = SPH_OK
  end function sph_density_filter

  !> Status of the first active particle with a non-finite field or a density outside
  !> [rho_min, rho_max] (0-based index in bad_particle), SPH_OK if none.
  function sph_check_state(prm, arr, bad_particle) result(status) bind(C, name="sph_check_state")
    type(sph_params_t), intent(in) :: prm
    type(sph_arrays_t), intent(in) :: arr
    integer(c_int64_t), intent(out) :: bad_particle
    integer(c_int) :: status
    type(state_t) :: st
    logical :: ok
    status = SPH_ERR_ARGUMENT
    bad_particle = -1
    call bind_state(arr, st, .false., .false., ok)
    if (.not. ok) return
    call check_finite(prm, st, bad_particle, status)
  end function sph_check_state

  !> The active fluid rings to split (domain.split_axis_rings; physics/axisymmetric.f90,
  !> ring_too_heavy): their 0-based indices, at most capacity of them, and how many there are.
  function sph_axis_rings_to_split(prm, arr, capacity, idx, n_found) result(status) &
      bind(C, name="sph_axis_rings_to_split")
    type(sph_params_t), intent(in) :: prm
    type(sph_arrays_t), intent(in) :: arr
    integer(c_int64_t), value :: capacity
    integer(c_int64_t), intent(out) :: idx(*)
    integer(c_int64_t), intent(out) :: n_found
    integer(c_int) :: status
    type(state_t) :: st
    logical :: ok
    status = SPH_ERR_ARGUMENT
    n_found = 0
    if (capacity < 0) return
    call bind_state(arr, st, .false., .false., ok)
    if (.not. ok) return
    call rings_to_split(prm, st, capacity, idx, n_found)
    status = SPH_OK
  end function sph_axis_rings_to_split

  !> Pair rates (ax, az, ar, XSPH) at the current state, gravity excluded; visc_max returns
  !> max (u_ab . r_ab)/(r_ab^2 + eta^2). For tests and diagnostics.
  function sph_compute_rates(ws_handle, prm, arr, visc_max) result(status) &
      bind(C, name="sph_compute_rates")
    type(c_ptr), value :: ws_handle
    type(sph_params_t), intent(in) :: prm
    type(sph_arrays_t), intent(in) :: arr
    real(c_double), intent(out) :: visc_max
    integer(c_int) :: status
    type(workspace_t), pointer :: ws
    type(state_t) :: st
    logical :: ok
    status = SPH_ERR_ARGUMENT
    visc_max = 0.0_rp
    if (.not. c_associated(ws_handle)) return
    if (.not. params_ok(prm)) return
    call bind_state(arr, st, .true., prm%boundary%model == BC_REPULSIVE, ok)
    if (.not. ok) return
    call c_f_pointer(ws_handle, ws)
    call compute_rates(prm, kernel_setup(prm%numerics%kernel, prm%numerics%h), st, ws%sorted, visc_max)
    status = SPH_OK
  end function sph_compute_rates

  !> CSF fields of the current state without stepping (tests, diagnostics): colour, normal n
  !> (unnormalised colour gradient) and curvature into arr%colour, st_nx, st_nz, kappa (all
  !> four required) and, when arr%ax and arr%az are given, the surface-tension acceleration
  !> alone (eq 24: no pair forces, no gravity; 0 where sigma = 0) into them.
  function sph_surface_tension_fields(ws_handle, prm, arr) result(status) &
      bind(C, name="sph_surface_tension_fields")
    type(c_ptr), value :: ws_handle
    type(sph_params_t), intent(in) :: prm
    type(sph_arrays_t), intent(in) :: arr
    integer(c_int) :: status
    type(workspace_t), pointer :: ws
    type(state_t) :: st
    logical :: ok
    real(rp), pointer, contiguous :: ax(:), az(:)
    integer :: k
    status = SPH_ERR_ARGUMENT
    if (.not. c_associated(ws_handle)) return
    if (.not. params_ok(prm)) return
    call bind_state(arr, st, .false., .false., ok)
    if (.not. ok) return
    if (st%n > 0 .and. .not. (associated(st%colour) .and. associated(st%st_nx) .and. &
                              associated(st%st_nz) .and. associated(st%kappa))) return
    ! the rings pair's CSF force needs its rates (axisymmetric_loops.f90): fields only
    if (prm%geometry%axis_pair == AXIS_PAIR_RINGS .and. c_associated(arr%ax)) return
    call c_f_pointer(ws_handle, ws)
    call gather_sorted(st, prm%numerics%h, ws%sorted, prm)
    if (prm%geometry%axis_pair == AXIS_PAIR_RINGS .and. allocated(ws%sorted%axi_dx)) &
      deallocate(ws%sorted%axi_dx, ws%sorted%axi_dz)   ! not this state's
    call surface_tension_rates(prm, kernel_setup(prm%numerics%kernel, prm%numerics%h), st, ws%sorted)
    if (c_associated(arr%ax) .and. c_associated(arr%az)) then
      call c_f_pointer(arr%ax, ax, [st%n])
      call c_f_pointer(arr%az, az, [st%n])
      ax = 0.0_rp
      az = 0.0_rp
      do k = 1, ws%sorted%n
        if (ws%sorted%grid%order(k) > st%n) cycle   ! an image slot
        ax(ws%sorted%grid%order(k)) = ws%sorted%rate(R_AX, k)
        az(ws%sorted%grid%order(k)) = ws%sorted%rate(R_AZ, k)
      end do
    end if
    status = SPH_OK
  end function sph_surface_tension_fields

  !> W(r) and F(r) = (dW/dr)/r for n distances.
  function sph_kernel_eval(kernel, h, n, r, w, f) result(status) bind(C, name="sph_kernel_eval")
    integer(c_int), value :: kernel
    real(c_double), value :: h
    integer(c_int64_t), value :: n
    real(c_double), intent(in) :: r(n)
    real(c_double), intent(out) :: w(n), f(n)
    integer(c_int) :: status
    type(kernel_t) :: k
    integer(i8) :: i
    status = SPH_ERR_ARGUMENT
    if (.not. kernel_valid(kernel) .or. .not. (h > 0.0_rp) .or. n < 0) return
    k = kernel_setup(kernel, h)
    do i = 1, n
      if (r(i) <= 0.0_rp .or. r(i) >= 2.0_rp * h) then
        w(i) = 0.0_rp
        f(i) = 0.0_rp
        if (r(i) == 0.0_rp) call kernel_eval(k, tiny(1.0_rp), w(i), f(i))
        if (r(i) == 0.0_rp) f(i) = 0.0_rp
      else
        call kernel_eval(k, r(i), w(i), f(i))
      end if
    end do
    status = SPH_OK
  end function sph_kernel_eval

  !> The surface fit's parabola (physics/surface_tension.f90: csf_fit_point, csf_fit_curvature)
  !> through n points (px, pz) with weights om, seen from a particle at the origin with unit
  !> normal (nx, nz) and particle spacing sqrt(V) = spacing, refused through fewer than
  !> points_min points (surface_tension.fit_points_min; 3 or less: the three a parabola needs,
  !> no more): its in-plane curvature kin,
  !> the radial part nrx of its normal and its point's offset c0 along the normal; fitted = 0
  !> where the fit is refused (kin, nrx, c0 then 0), 1 where it is taken, 2 where it is refused
  !> for too few points.
  function sph_surface_fit(n, px, pz, om, nx, nz, spacing, points_min, kin, nrx, c0, fitted) &
      result(status) bind(C, name="sph_surface_fit")
    integer(c_int64_t), value :: n
    real(c_double), intent(in) :: px(n), pz(n), om(n)
    real(c_double), value :: nx, nz, spacing
    integer(c_int), value :: points_min
    real(c_double), intent(out) :: kin, nrx, c0
    integer(c_int), intent(out) :: fitted
    integer(c_int) :: status
    real(rp) :: fit(N_FIT)
    logical :: ok, sparse
    integer(i8) :: i
    status = SPH_ERR_ARGUMENT
    kin = 0.0_rp
    nrx = 0.0_rp
    c0 = 0.0_rp
    fitted = 0
    if (n < 0 .or. .not. (spacing > 0.0_rp) .or. abs(hypot(nx, nz) - 1.0_rp) > 1.0e-12_rp &
        .or. points_min < 0) return
    fit = 0.0_rp
    do i = 1, n
      call csf_fit_point(om(i), px(i), pz(i), nx, nz, fit)
    end do
    call csf_fit_curvature(fit, nx, nz, spacing, points_min, kin, nrx, c0, ok, sparse)   ! refused: nothing set
    fitted = merge(1, merge(2, 0, sparse), ok)
    status = SPH_OK
  end function sph_surface_fit

  !> All pairs (i < j, 0-based) of active particles closer than 2h, found by the cell search.
  function sph_neighbour_pairs(prm, arr, capacity, pi_, pj_, npairs) result(status) &
      bind(C, name="sph_neighbour_pairs")
    type(sph_params_t), intent(in) :: prm
    type(sph_arrays_t), intent(in) :: arr
    integer(c_int64_t), value :: capacity
    integer(c_int64_t), intent(out) :: pi_(capacity), pj_(capacity)
    integer(c_int64_t), intent(out) :: npairs
    integer(c_int) :: status
    type(state_t) :: st
    type(sorted_t) :: s
    type(pair_list_t) :: pl
    logical :: ok
    integer :: row, k, ia, ib
    status = SPH_ERR_ARGUMENT
    npairs = 0
    if (.not. (prm%numerics%h > 0.0_rp)) return
    call bind_state(arr, st, .false., .false., ok)
    if (.not. ok) return
    ! a list of exactly the pairs closer than 2h, boundary-boundary pairs included
    st%list_x => null()
    st%list_z => null()
    s%skin_per_h = 0.0_rp
    s%all_pairs = .true.
    call gather_sorted(st, prm%numerics%h, s)
    status = SPH_OK
    do row = 0, s%grid%ncz - 1
      call build_row_pairs(s, row, 4.0_rp * prm%numerics%h * prm%numerics%h, PAIRS_ALL, pl)
      do k = 1, pl%n
        npairs = npairs + 1
        if (npairs > capacity) then
          status = SPH_ERR_CAPACITY
          cycle
        end if
        ia = s%grid%order(pl%a(k))
        ib = s%grid%order(pl%b(k))
        pi_(npairs) = min(ia, ib) - 1
        pj_(npairs) = max(ia, ib) - 1
      end do
    end do
  end function sph_neighbour_pairs

  !> Tait EoS for n densities.
  function sph_eos(prm, n, rho, p, c) result(status) bind(C, name="sph_eos")
    type(sph_params_t), intent(in) :: prm
    integer(c_int64_t), value :: n
    real(c_double), intent(in) :: rho(n)
    real(c_double), intent(out) :: p(n), c(n)
    integer(c_int) :: status
    status = SPH_ERR_ARGUMENT
    if (n < 0 .or. .not. (prm%eos%rho0 > 0.0_rp)) return
    p = tait_pressure(rho, prm%eos%rho0, prm%eos%b, prm%eos%gamma)
    c = tait_sound_speed(rho, prm%eos%rho0, prm%eos%c0)
    status = SPH_OK
  end function sph_eos

end module sphjet_capi
