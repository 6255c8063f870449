!> surface_tension.balance_free_bodies (cases/CASE_FORMAT.md): the bodies of fluid that hang
!> together by their kernel pairs, and the surface tension's net force taken off those that are
!> free. Called by loops/surface_tension_loops.f90 once the CSF force is in the slots' rates.
module free_body_loops
  use sphjet_kinds, only: rp
  use sphjet_types, only: sph_params_t
  use axisymmetric, only: mass_per_radian
  use nozzle_geometry, only: in_driven_nozzle
  use sorted_state, only: sorted_t, R_AX, R_AZ
  implicit none
  private
  public :: balance_free_bodies

contains

  !> The surface tension's net force on each free body taken off as a uniform acceleration of
  !> that body. A body is a set of fluid particles joined by
  !> pairs closer than 2h (the pairs the colour pass kept, images standing for their sources);
  !> it is free when none of its particles is a boundary particle or lies in a driven nozzle's
  !> plug (physics/nozzle_geometry.f90). Under a uniform sigma the net force of a closed surface
  !> is zero, and so is the pressure pair's (it is antisymmetric); the CSF force
  !> -(sigma/rho_a) kappa_a d_a is not: its sum over a body, -sigma sum_a V_a kappa_a d_a,
  !> vanishes only where kappa is uniform. On a fragment of a few particles kappa is anything but
  !> uniform: a torus of 22 rings (R = 0.16 mm at r = 1.3 mm, h = 2 dx = 0.12 mm, sigma = 0.072
  !> N/m) gained 0.5 m/s along z as it closed on the axis, without surface tension 0.001 m/s.
  !> Axisymmetric: along z only (a ring's radial net force is physical: it contracts); planar:
  !> along x and z. a0 holds the slots' accelerations before the surface tension was added. The
  !> union-find and the sums run on one thread, in slot order: the result does not depend on the
  !> thread count.
  subroutine balance_free_bodies(prm, s, a0, axi)
    type(sph_params_t), intent(in) :: prm
    type(sorted_t), intent(inout) :: s
    real(rp), intent(in) :: a0(:, :)
    logical, intent(in) :: axi
    integer, allocatable :: parent(:)
    logical, allocatable :: held(:)
    real(rp), allocatable :: fx(:), fz(:), mass(:)
    integer :: n, r, q, k, a, b
    real(rp) :: mk
    logical :: nozzle
    if (.not. allocated(s%cache) .or. .not. prm%surface_tension%sigma > 0.0_rp) return
    n = s%n
    nozzle = prm%nozzle%u > 0.0_rp
    allocate(parent(n), held(n), fx(n), fz(n), mass(n))
    do k = 1, n
      parent(k) = k
    end do
    do r = 0, s%grid%ncz - 1
      do q = 1, s%cache(r)%n
        a = find(s%src_slot(s%cache(r)%a(q)))
        b = find(s%src_slot(s%cache(r)%b(q)))
        if (a /= b) parent(max(a, b)) = min(a, b)
      end do
    end do
    held = .false.
    fx = 0.0_rp
    fz = 0.0_rp
    mass = 0.0_rp
    do k = 1, n
      if (s%src_slot(k) /= k) cycle   ! an image: its source counts
      a = find(k)
      if (.not. s%fluid(k)) then
        held(a) = .true.
        cycle
      end if
      if (nozzle) then
        if (in_driven_nozzle(prm, s%x(k), s%z(k))) held(a) = .true.
      end if
      ! the ring's mass (over 2 pi) in the axisymmetric geometry, where s%m is the planar mass
      mk = merge(mass_per_radian(s%m(k), s%x(k), prm%numerics%h), s%m(k), axi)
      fx(a) = fx(a) + mk * (s%rate(R_AX, k) - a0(1, k))
      fz(a) = fz(a) + mk * (s%rate(R_AZ, k) - a0(2, k))
      mass(a) = mass(a) + mk
    end do
    do k = 1, n
      if (s%src_slot(k) /= k .or. .not. s%fluid(k)) cycle
      a = find(k)
      if (held(a)) cycle
      if (.not. axi) s%rate(R_AX, k) = s%rate(R_AX, k) - fx(a) / mass(a)
      s%rate(R_AZ, k) = s%rate(R_AZ, k) - fz(a) / mass(a)
    end do
  contains
    !> The root of k's body, the path to it halved on the way.
    integer function find(k0)
      integer, intent(in) :: k0
      integer :: j
      j = k0
      do while (parent(j) /= j)
        parent(j) = parent(parent(j))
        j = parent(j)
      end do
      find = j
    end function find
  end subroutine balance_free_bodies

end module free_body_loops
