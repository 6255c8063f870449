!> The data layout shared with C++ (mirrored field by field in capi/sphjet_core.h):
!> the scalar parameters, the particle arrays lent by C++ (pointers + count), and the
!> per-step report. Internal code sees the arrays through state_t (Fortran pointers).
module sphjet_types
  use, intrinsic :: iso_c_binding, only: c_ptr, c_double, c_int, c_int64_t, c_null_ptr, &
                                         c_associated, c_f_pointer
  use sphjet_kinds, only: rp, ip, i8
  implicit none
  private
  public :: sph_params_t, sph_numerics_t, sph_time_step_t, sph_eos_t, sph_domain_t, &
            sph_viscosity_t, sph_boundary_t, sph_surface_tension_t, sph_nozzle_t, &
            sph_geometry_t, sph_gravity_t, sph_arrays_t, sph_step_info_t, state_t, bind_state

  !> Kernel, smoothing length and the corrections applied to the SPH sums
  !> (C struct sph_numerics_t).
  type, bind(C) :: sph_numerics_t
    integer(c_int) :: kernel = 5             !< 1 Gaussian, 2 quadratic, 3 cubic spline, 5 Wendland
    integer(c_int) :: density_filter = 0     !< 0 none, 1 Shepard, 2 MLS
    integer(c_int) :: tensile = 0            !< 1: tensile-instability correction on
    integer(c_int) :: integrator = 1         !< 1 predictor-corrector, 2 leapfrog (fluid alone)
    real(c_double) :: h = 0.0_rp             !< smoothing length [m]
    real(c_double) :: xsph_eps = 0.5_rp      !< XSPH epsilon
    real(c_double) :: density_diffusion = 0.0_rp !< delta of the density diffusion; 0 = off
    real(c_double) :: bulk_viscosity = 0.0_rp    !< beta of the bulk viscosity beta rho0 c0 h; 0 = off
    real(c_double) :: shifting = 0.0_rp      !< A of the shifting velocity -A h (c0/10) grad C; 0 = off
  end type sph_numerics_t

  !> Time-step control (C struct sph_time_step_t).
  type, bind(C) :: sph_time_step_t
    integer(c_int) :: variable_dt = 1        !< 1: dt from CFL each step
    real(c_double) :: cfl = 0.2_rp           !< Courant number
    real(c_double) :: dt_min = 0.0_rp        !< a step below this is a collapse [s]
    real(c_double) :: dt_max = 0.0_rp        !< the variable step's cap [s]; 0: none
  end type sph_time_step_t

  !> Tait equation of state (C struct sph_eos_t).
  type, bind(C) :: sph_eos_t
    real(c_double) :: rho0 = 1000.0_rp       !< reference density [kg/m^3]
    real(c_double) :: b = 0.0_rp             !< Tait B [Pa]
    real(c_double) :: gamma = 7.0_rp         !< Tait exponent
    real(c_double) :: c0 = 0.0_rp            !< sound speed at rho0 [m/s]
  end type sph_eos_t

  !> Where and in what state a particle may be (C struct sph_domain_t).
  type, bind(C) :: sph_domain_t
    integer(c_int) :: remove_out = 1         !< 1: remove leavers and count, 0: error
    real(c_double) :: xmin = 0.0_rp, xmax = 0.0_rp  !< fluid beyond leaves the domain [m]
    real(c_double) :: zmin = 0.0_rp, zmax = 0.0_rp
    real(c_double) :: rho_min = 0.0_rp, rho_max = 0.0_rp  !< sane density band [kg/m^3]
  end type sph_domain_t

  !> Fluid viscosity (C struct sph_viscosity_t).
  type, bind(C) :: sph_viscosity_t
    integer(c_int) :: model = 1              !< 1 artificial, 2 laminar
    real(c_double) :: value = 0.0_rp         !< alpha (artificial) or nu [m^2/s] (laminar)
    real(c_double) :: artificial_alpha = 0.0_rp  !< laminar: an artificial alpha on top; 0 = off
    integer(c_int) :: reconstruct = 0        !< 1: Pi of the velocity jump left after the linear
                                             !< reconstruction to the pair's midpoint
  end type sph_viscosity_t

  !> Boundary particles: the wall model and the moving gate (C struct sph_boundary_t).
  type, bind(C) :: sph_boundary_t
    integer(c_int) :: model = 2              !< 1 repulsive (Monaghan-Kos), 2 dynamic
    integer(c_int) :: dbc_period = 1         !< steps between dynamic-boundary density updates
    real(c_double) :: coef = 10.0_rp         !< speed-of-sound coefficient (repulsive walls)
    real(c_double) :: h_swl = 1.0_rp         !< still-water depth [m] (repulsive walls)
    real(c_double) :: viscosity = 0.0_rp     !< nu of the repulsive-wall viscous term [m^2/s]
    real(c_double) :: gate_vx = 0.0_rp       !< moving boundary (gate) velocity from gate_t_start [m/s]
    real(c_double) :: gate_vz = 0.0_rp
    real(c_double) :: gate_t_start = 0.0_rp  !< time the gate starts moving [s]
    real(c_double) :: gate_z_cap = 0.0_rp    !< a gate particle rises no higher [m]
  end type sph_boundary_t

  !> CSF surface tension (C struct sph_surface_tension_t).
  type, bind(C) :: sph_surface_tension_t
    integer(c_int) :: delta = 0              !< CSF delta in eq 24: 0 pressure-consistent,
                                             !< 1 colour gradient (paper)
    integer(c_int) :: rings_curvature = 0    !< rings pair's surface rows: 0 neighbours' mean, 1 own
    integer(c_int) :: curvature_normals = 0  !< free-surface curvature's normals: 0 all, 1 within h
    integer(c_int) :: curvature = 0          !< free-surface curvature: 0 the normals' divergence, 1 surface fit
    integer(c_int) :: free_bodies = 0        !< 1: each free body's net surface-tension force removed
    integer(c_int) :: thin_rings = 0         !< 1: free rings thinner than the kernel take the normals' curvature
    integer(c_int) :: fit_points_min = 3     !< the fewest points a surface fit may pass through (0-3: a parabola's 3)
    real(c_double) :: sigma = 0.0_rp         !< surface tension [N/m]; 0 = off
  end type sph_surface_tension_t

  !> Driven nozzle (C struct sph_nozzle_t).
  type, bind(C) :: sph_nozzle_t
    real(c_double) :: u = 0.0_rp             !< plug speed along the axis [m/s]; 0 = no nozzle
    real(c_double) :: x0 = 0.0_rp, z0 = 0.0_rp  !< orifice centre [m]
    real(c_double) :: ex = 0.0_rp, ez = -1.0_rp !< unit jet axis (flow direction)
    real(c_double) :: half_width = 0.0_rp    !< plug half-width across the axis [m]
    real(c_double) :: profile_a = 0.0_rp     !< parabolic exit profile's wall distance [m]; 0 = rigid plug
    real(c_double) :: profile_k = 0.0_rp     !< its centre speed / u (the lattice's flux equals u's)
    real(c_double) :: profile_lmax = 0.0_rp  !< the outer line's distance: farther fluid moves with it [m]
    real(c_double) :: profile_rho = 0.0_rp   !< the density a profiled plug holds [kg/m^3]
    integer(c_int) :: release = 0            !< 1: a plug particle turns free at its crossing of the orifice line;
                                             !< 2: that, and the step lands the rows on the line (landed_step)
  end type sph_nozzle_t

  !> Planar or axisymmetric, periodicity, and the axisymmetric pair (C struct sph_geometry_t).
  type, bind(C) :: sph_geometry_t
    integer(c_int) :: kind = 0               !< 0 planar (x, z); 1 axisymmetric (x = r >= 0, axis x = 0)
    integer(c_int) :: periodic_z = 0         !< 1: periodic in z with period domain%zmax - domain%zmin
    integer(c_int) :: axis_pair = 0          !< axisymmetric pair: 0 smoothed radius, 1 rings
    real(c_double) :: axis_m1 = 0.0_rp       !< rings pair: a ring lighter is in the first column [kg]
    real(c_double) :: ring_mass_per_radius = 0.0_rp !< split_axis_rings: 2 pi rho0 dx dz [kg/m]; 0 = off
    integer(c_int) :: renormalise_continuity = 0 !< rings pair: 1 its continuity renormalised along r and z
    real(c_double) :: renormalise_reach = 0.0_rp !< > 0: renormalised only nearer the orifice than this [m]
    integer(c_int) :: bound_xsph = 0         !< rings pair: 1 each ring's XSPH over max(1, its kernel sum)
  end type sph_geometry_t

  !> Body force (C struct sph_gravity_t).
  type, bind(C) :: sph_gravity_t
    real(c_double) :: gx = 0.0_rp, gz = -9.81_rp  !< gravity [m/s^2]
  end type sph_gravity_t

  !> Scalar parameters of a run, one member per concern (C struct sph_params_t). A new
  !> parameter goes into the group of its concern, here and in capi/sphjet_core.h.
  type, bind(C) :: sph_params_t
    type(sph_numerics_t) :: numerics
    type(sph_time_step_t) :: time_step
    type(sph_eos_t) :: eos
    type(sph_domain_t) :: domain
    type(sph_viscosity_t) :: viscosity
    type(sph_boundary_t) :: boundary
    type(sph_surface_tension_t) :: surface_tension
    type(sph_nozzle_t) :: nozzle
    type(sph_geometry_t) :: geometry
    type(sph_gravity_t) :: gravity
  end type sph_params_t

  !> The particle arrays (C struct sph_arrays_t). All arrays have n entries, particles in
  !> legacy order (boundary first); C++ owns them. Optional arrays may be null.
  type, bind(C) :: sph_arrays_t
    integer(c_int64_t) :: n = 0, nb = 0
    type(c_ptr) :: x = c_null_ptr, z = c_null_ptr, u = c_null_ptr, w = c_null_ptr
    type(c_ptr) :: rho = c_null_ptr, p = c_null_ptr, c = c_null_ptr, m = c_null_ptr
    type(c_ptr) :: kind = c_null_ptr, active = c_null_ptr
    ! integrator work space (start-of-step values and rates)
    type(c_ptr) :: xo = c_null_ptr, zo = c_null_ptr, uo = c_null_ptr, wo = c_null_ptr
    type(c_ptr) :: rhoo = c_null_ptr
    type(c_ptr) :: ax = c_null_ptr, az = c_null_ptr, ar = c_null_ptr
    type(c_ptr) :: xsph_u = c_null_ptr, xsph_w = c_null_ptr
    ! repulsive walls: unit normal and spacing to the wall neighbours (boundary particles)
    type(c_ptr) :: wall_prev = c_null_ptr, wall_next = c_null_ptr  !< int, 0-based
    type(c_ptr) :: wall_nx = c_null_ptr, wall_nz = c_null_ptr
    type(c_ptr) :: wall_dback = c_null_ptr, wall_dfwd = c_null_ptr
    ! surface tension fields (may be null when sigma = 0)
    type(c_ptr) :: colour = c_null_ptr, st_nx = c_null_ptr, st_nz = c_null_ptr
    type(c_ptr) :: kappa = c_null_ptr
    ! positions at the last neighbour-list build (may be null; NaN = no list yet). A
    ! checkpoint that keeps them lets a resumed run list the pairs in the same order.
    type(c_ptr) :: list_x = c_null_ptr, list_z = c_null_ptr
  end type sph_arrays_t

  !> What one step did (C struct sph_step_info_t).
  type, bind(C) :: sph_step_info_t
    real(c_double) :: dt = 0.0_rp        !< in: step to take; out: step taken [s]
    real(c_double) :: time = 0.0_rp      !< in: time at the start of the step [s]
    real(c_double) :: dt_next = 0.0_rp   !< step for the next call [s]
    real(c_double) :: dt_f = 0.0_rp, dt_cv = 0.0_rp, dt_new = 0.0_rp  !< last CFL terms [s]
    real(c_double) :: visc_dt = 0.0_rp   !< max_ab (u_ab . r_ab)/(r^2 + eta^2) [1/s]
    integer(c_int64_t) :: dbc_counter = 0 !< in/out: steps since last boundary density update
    integer(c_int64_t) :: n_removed = 0  !< out: particles removed in this step
    integer(c_int64_t) :: bad_particle = -1 !< out: 0-based index of the offending particle
    integer(c_int) :: bad_cause = 0      !< out: status code of the failure
    integer(c_int) :: rates_kept = 0     !< in/out (leapfrog): 1 when ax, az, ar and XSPH are the
                                         !< rates of the state as it is
  end type sph_step_info_t

  !> Internal view of the arrays.
  type :: state_t
    integer :: n = 0, nb = 0
    real(rp), pointer, contiguous :: x(:) => null(), z(:) => null(), u(:) => null(), w(:) => null()
    real(rp), pointer, contiguous :: rho(:) => null(), p(:) => null(), c(:) => null(), m(:) => null()
    integer(ip), pointer, contiguous :: kind(:) => null(), active(:) => null()
    real(rp), pointer, contiguous :: xo(:) => null(), zo(:) => null(), uo(:) => null(), wo(:) => null()
    real(rp), pointer, contiguous :: rhoo(:) => null()
    real(rp), pointer, contiguous :: ax(:) => null(), az(:) => null(), ar(:) => null()
    real(rp), pointer, contiguous :: xsph_u(:) => null(), xsph_w(:) => null()
    integer(ip), pointer, contiguous :: wall_prev(:) => null(), wall_next(:) => null()
    real(rp), pointer, contiguous :: wall_nx(:) => null(), wall_nz(:) => null()
    real(rp), pointer, contiguous :: wall_dback(:) => null(), wall_dfwd(:) => null()
    real(rp), pointer, contiguous :: colour(:) => null(), st_nx(:) => null(), st_nz(:) => null()
    real(rp), pointer, contiguous :: kappa(:) => null()
    real(rp), pointer, contiguous :: list_x(:) => null(), list_z(:) => null()
  end type state_t

contains

  !> Binds the C arrays to a state_t. ok = .false. if a required pointer is null.
  !> need_work: integrator arrays required; need_wall: wall arrays required.
  subroutine bind_state(a, st, need_work, need_wall, ok)
    type(sph_arrays_t), intent(in) :: a
    type(state_t), intent(out) :: st
    logical, intent(in) :: need_work, need_wall
    logical, intent(out) :: ok
    integer :: n
    ok = .false.
    if (a%n < 0 .or. a%nb < 0 .or. a%nb > a%n) return
    n = int(a%n)
    st%n = n
    st%nb = int(a%nb)
    if (.not. bindr(a%x, st%x)) return
    if (.not. bindr(a%z, st%z)) return
    if (.not. bindr(a%u, st%u)) return
    if (.not. bindr(a%w, st%w)) return
    if (.not. bindr(a%rho, st%rho)) return
    if (.not. bindr(a%p, st%p)) return
    if (.not. bindr(a%c, st%c)) return
    if (.not. bindr(a%m, st%m)) return
    if (.not. bindi(a%kind, st%kind)) return
    if (.not. bindi(a%active, st%active)) return
    if (need_work) then
      if (.not. bindr(a%xo, st%xo)) return
      if (.not. bindr(a%zo, st%zo)) return
      if (.not. bindr(a%uo, st%uo)) return
      if (.not. bindr(a%wo, st%wo)) return
      if (.not. bindr(a%rhoo, st%rhoo)) return
      if (.not. bindr(a%ax, st%ax)) return
      if (.not. bindr(a%az, st%az)) return
      if (.not. bindr(a%ar, st%ar)) return
      if (.not. bindr(a%xsph_u, st%xsph_u)) return
      if (.not. bindr(a%xsph_w, st%xsph_w)) return
    end if
    if (need_wall) then
      if (.not. bindi(a%wall_prev, st%wall_prev)) return
      if (.not. bindi(a%wall_next, st%wall_next)) return
      if (.not. bindr(a%wall_nx, st%wall_nx)) return
      if (.not. bindr(a%wall_nz, st%wall_nz)) return
      if (.not. bindr(a%wall_dback, st%wall_dback)) return
      if (.not. bindr(a%wall_dfwd, st%wall_dfwd)) return
    end if
    ! optional surface-tension fields
    if (c_associated(a%colour)) call c_f_pointer(a%colour, st%colour, [n])
    if (c_associated(a%st_nx)) call c_f_pointer(a%st_nx, st%st_nx, [n])
    if (c_associated(a%st_nz)) call c_f_pointer(a%st_nz, st%st_nz, [n])
    if (c_associated(a%kappa)) call c_f_pointer(a%kappa, st%kappa, [n])
    ! optional neighbour-list build positions (both or none)
    if (c_associated(a%list_x) .and. c_associated(a%list_z)) then
      call c_f_pointer(a%list_x, st%list_x, [n])
      call c_f_pointer(a%list_z, st%list_z, [n])
    end if
    ok = .true.

  contains

    logical function bindr(cp, fp)
      type(c_ptr), intent(in) :: cp
      real(rp), pointer, contiguous, intent(out) :: fp(:)
      bindr = c_associated(cp) .or. n == 0
      if (c_associated(cp)) then
        call c_f_pointer(cp, fp, [n])
      else
        fp => null()
      end if
    end function bindr

    logical function bindi(cp, fp)
      type(c_ptr), intent(in) :: cp
      integer(ip), pointer, contiguous, intent(out) :: fp(:)
      bindi = c_associated(cp) .or. n == 0
      if (c_associated(cp)) then
        call c_f_pointer(cp, fp, [n])
      else
        fp => null()
      end if
    end function bindi

  end subroutine bind_state

end module sphjet_types
