!> Kinds, constants and status codes shared by every module of the core.
module sphjet_kinds
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t
  implicit none
  private

  integer, parameter, public :: rp = c_double   !< real kind of every particle field
  integer, parameter, public :: ip = c_int
  integer, parameter, public :: i8 = c_int64_t

  real(rp), parameter, public :: pi = 3.14159265358979323846264338327950288_rp

  ! Status codes returned through the C interface (mirrored in capi/sphjet_core.h).
  integer(ip), parameter, public :: SPH_OK = 0
  integer(ip), parameter, public :: SPH_ERR_ARGUMENT = 1     !< bad count, null pointer, bad option
  integer(ip), parameter, public :: SPH_ERR_NONFINITE = 2    !< NaN or Inf in a field
  integer(ip), parameter, public :: SPH_ERR_DENSITY = 3      !< density outside the allowed band
  integer(ip), parameter, public :: SPH_ERR_OUT_OF_DOMAIN = 4 !< particle left the domain (not removed)
  integer(ip), parameter, public :: SPH_ERR_DT_COLLAPSE = 5  !< time step below the floor
  integer(ip), parameter, public :: SPH_ERR_CAPACITY = 6     !< output buffer too small

  ! Option values (numbered as in the legacy case file). KERNEL_CUBIC_TC takes the number
  ! legacy SPHysics leaves unused (its case files refuse 4); KERNEL_WENDLAND is the largest.
  integer(ip), parameter, public :: KERNEL_GAUSSIAN = 1, KERNEL_QUADRATIC = 2, &
                                    KERNEL_CUBIC = 3, KERNEL_CUBIC_TC = 4, KERNEL_WENDLAND = 5
  integer(ip), parameter, public :: VISC_ARTIFICIAL = 1, VISC_LAMINAR = 2
  integer(ip), parameter, public :: BC_REPULSIVE = 1, BC_DYNAMIC = 2
  integer(ip), parameter, public :: FILTER_NONE = 0, FILTER_SHEPARD = 1, FILTER_MLS = 2
  integer(ip), parameter, public :: GEOM_PLANAR = 0, GEOM_AXISYMMETRIC = 1  !< sph_params_t%geometry%kind
  integer(ip), parameter, public :: INTEGRATOR_PC = 1, INTEGRATOR_LEAPFROG = 2  !< %numerics%integrator
  integer(ip), parameter, public :: NOZZLE_RELEASE_STEP = 0, NOZZLE_RELEASE_CROSSING = 1, &
                                     NOZZLE_RELEASE_LANDED = 2  !< %nozzle%release
  integer(ip), parameter, public :: AXIS_PAIR_SMOOTHED_RADIUS = 0, AXIS_PAIR_RINGS = 1  !< %axis_pair
  integer(ip), parameter, public :: RINGS_CURVATURE_MEAN = 0, RINGS_CURVATURE_OWN = 1  !< %rings_curvature
  integer(ip), parameter, public :: CURV_NORMALS_ALL = 0, CURV_NORMALS_BAND = 1  !< %curvature_normals
  integer(ip), parameter, public :: CURVATURE_NORMALS = 0, CURVATURE_SURFACE_FIT = 1  !< %curvature
  integer(ip), parameter, public :: KIND_FIXED_BOUNDARY = 0, KIND_MOVING_BOUNDARY = 1, &
                                    KIND_FLUID = 2
end module sphjet_kinds
