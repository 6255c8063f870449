!> surface_tension.balance_free_bodies (cases/CASE_FORMAT.md): the bodies of fluid that hang
!> together by their kernel pairs, and the surface tension's net force taken off those that are
!> free. Called by loops/surface_tension_loops.f90 once the CSF force is in the slots' rates.
module free_body_loops
  use sphjet_kinds, only: rp, pi
  use sphjet_types, only: sph_params_t
  use axisymmetric, only: mass_per_radian
  use nozzle_geometry, only: in_driven_nozzle
  use sorted_state, only: sorted_t, R_AX, R_AZ
  implicit none
  private
  public :: bodies_of, balance_free_bodies, thin_free_rings

  !> surface_tension.thin_rings_normals: a free ring (a free body with no particle within h of
  !> the axis) whose meridian cross-section A is narrower than a tube of radius THIN_RING_H h,
  !> sqrt(A / pi) < THIN_RING_H h, takes the normals' curvature instead of the surface fit. A
  !> torus fragment's rings pack as 1/r as it flies out (each keeps its mass and density); once
  !> its tube is narrower than the kernel's reach the fit draws it too sharply bent: a torus of
  !> b = 0.2 mm at R = 0.6 mm flung outward at 1 m/s (cases/round_jet/torus_fragment.toml,
  !> h = 2 dx = 0.119 mm) was pulled back at 0.6-0.95 of its surface energy's sigma / (rho R b)
  !> while b > 1.3 h and at up to 3.9 times it below; with half the spacing, at 0.79-0.94
  !> (cases/round_jet/README.md, "Fragments that fly"). 1.5 h lies above where the excess starts:
  !> there the fit still pulls at 0.6-0.7 of the rate and the normals at 0.5-0.8, and a ring that
  !> flies on only thins.
  real(rp), parameter :: THIN_RING_H = 1.5_rp

contains

  !> The bodies of fluid: root(k) the body of slot k (a source slot; an image's is its
  !> source's), held(root) whether that body touches a boundary particle or a driven nozzle's
  !> plug. A body is a set of fluid particles joined by pairs closer than 2h (the pairs the
  !> colour pass kept, images standing for their sources). The union-find runs on one thread, in
  !> slot order. Found once per surface-tension evaluation, for balance_free_bodies and
  !> thin_free_rings alike; left unallocated without the colour pass's pairs.
  subroutine bodies_of(prm, s, root, held)
    type(sph_params_t), intent(in) :: prm
    type(sorted_t), intent(in) :: s
    integer, allocatable, intent(out) :: root(:)
    logical, allocatable, intent(out) :: held(:)
    integer :: n, r, q, k, a, b
    logical :: nozzle
    if (.not. allocated(s%cache)) return
    n = s%n
    allocate(root(n), held(n))
    nozzle = prm%nozzle%u > 0.0_rp
    do k = 1, n
      root(k) = k
    end do
    do r = 0, s%grid%ncz - 1
      do q = 1, s%cache(r)%n
        a = find(s%src_slot(s%cache(r)%a(q)))
        b = find(s%src_slot(s%cache(r)%b(q)))
        if (a /= b) root(max(a, b)) = min(a, b)
      end do
    end do
    held = .false.
    do k = 1, n
      root(k) = find(s%src_slot(k))
      if (s%src_slot(k) /= k) cycle
      if (.not. s%fluid(k)) then
        held(root(k)) = .true.
      else if (nozzle) then
        if (in_driven_nozzle(prm, s%x(k), s%z(k))) held(root(k)) = .true.
      end if
    end do
  contains
    !> The root of k's body, the path to it halved on the way.
    integer function find(k0)
      integer, intent(in) :: k0
      integer :: j
      j = k0
      do while (root(j) /= j)
        root(j) = root(root(j))
        j = root(j)
      end do
      find = j
    end function find
  end subroutine bodies_of

  !> The slots (images too) of the free rings thinner than THIN_RING_H h (above) taken out of the
  !> surface fit: outer(k) = 0 and fit(:, k) = 0 (no self point, no count), so that their
  !> particles keep the normals' curvature; v the slots' meridian areas m / rho.
  subroutine thin_free_rings(prm, s, v, root, held, outer, fit)
    type(sph_params_t), intent(in) :: prm
    type(sorted_t), intent(in) :: s
    real(rp), intent(in) :: v(:)
    integer, intent(in) :: root(:)      ! bodies_of's
    logical, intent(in) :: held(:)
    real(rp), intent(inout) :: outer(:), fit(:, :)
    logical, allocatable :: on_axis(:)
    real(rp), allocatable :: area(:)
    integer :: n, k, a
    real(rp) :: h
    n = s%n
    h = prm%numerics%h
    allocate(on_axis(n), area(n))
    on_axis = .false.
    area = 0.0_rp
    do k = 1, n
      if (s%src_slot(k) /= k .or. .not. s%fluid(k)) cycle
      a = root(k)
      area(a) = area(a) + v(k)
      if (s%x(k) < h) on_axis(a) = .true.
    end do
    do k = 1, n
      a = root(k)
      if (held(a) .or. on_axis(a) .or. area(a) >= pi * (THIN_RING_H * h)**2) cycle
      outer(k) = 0.0_rp
      fit(:, k) = 0.0_rp
    end do
  end subroutine thin_free_rings

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
  subroutine balance_free_bodies(prm, s, a0, axi, root, held)
    type(sph_params_t), intent(in) :: prm
    type(sorted_t), intent(inout) :: s
    real(rp), intent(in) :: a0(:, :)
    logical, intent(in) :: axi
    integer, intent(in) :: root(:)      ! bodies_of's
    logical, intent(in) :: held(:)
    real(rp), allocatable :: fx(:), fz(:), mass(:)
    integer :: n, k, a
    real(rp) :: mk
    if (.not. prm%surface_tension%sigma > 0.0_rp) return
    n = s%n
    allocate(fx(n), fz(n), mass(n))
    fx = 0.0_rp
    fz = 0.0_rp
    mass = 0.0_rp
    do k = 1, n
      if (s%src_slot(k) /= k .or. .not. s%fluid(k)) cycle   ! an image: its source counts
      a = root(k)
      ! the ring's mass (over 2 pi) in the axisymmetric geometry, where s%m is the planar mass
      mk = merge(mass_per_radian(s%m(k), s%x(k), prm%numerics%h), s%m(k), axi)
      fx(a) = fx(a) + mk * (s%rate(R_AX, k) - a0(1, k))
      fz(a) = fz(a) + mk * (s%rate(R_AZ, k) - a0(2, k))
      mass(a) = mass(a) + mk
    end do
    do k = 1, n
      if (s%src_slot(k) /= k .or. .not. s%fluid(k)) cycle
      a = root(k)
      if (held(a)) cycle
      if (.not. axi) s%rate(R_AX, k) = s%rate(R_AX, k) - fx(a) / mass(a)
      s%rate(R_AZ, k) = s%rate(R_AZ, k) - fz(a) / mass(a)
    end do
  end subroutine balance_free_bodies

end module free_body_loops
