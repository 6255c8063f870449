!> The active particles gathered in cell order (contiguous per cell), the layout every pair
!> traversal works on; rates are accumulated here and scattered back afterwards.
!>
!> gather_sorted is the one place that decides the sorted set and the neighbour list
!> (neighbours/verlet_list.f90): the particles are sorted, and the pairs closer than
!> 2h + skin listed, at their positions at the last build (xb, zb); between builds the sorted
!> order and the list are kept and only the fields are gathered again. The list is built again
!> when a particle has moved more than skin/2 from xb, zb, or the active set has changed.
!>
!> Kill -9 + resume stays bitwise: the pair order depends only on the build positions, and
!> those live in the caller's arrays list_x, list_z (state_t), which a checkpoint keeps. A
!> resumed run (or any call whose list_x, list_z differ from the work space's) sorts and lists
!> from them again and gets the same order; the decision to build depends only on x, z,
!> list_x, list_z and the active flags. Without those arrays the work space keeps its own
!> copy (tests, diagnostics). list_x = NaN means "no list": build from the current positions.
module sorted_state
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use sphjet_kinds, only: rp, ip, KIND_FLUID
  use sphjet_types, only: state_t
  use cell_list, only: cell_grid_t, build_cell_list
  use pair_list, only: pair_list_t
  use verlet_list, only: row_list_t, build_verlet_rows
  !$ use omp_lib, only: omp_get_max_threads
  implicit none
  private
  public :: sorted_t, gather_sorted, thread_lists, SKIN_PER_H

  !> Skin of the neighbour list in units of h (cutoff 2h + skin). Case1 rebuilds every ~50
  !> steps with 0.3 h; 0.15 h ran at the same speed there (README, Performance).
  real(rp), parameter :: SKIN_PER_H = 0.3_rp

  type :: sorted_t
    integer :: n = 0
    type(cell_grid_t) :: grid
    real(rp), allocatable :: x(:), z(:), u(:), w(:), rho(:), p(:), c(:), m(:), pr(:)
    logical, allocatable :: fluid(:)
    ! accumulated rates (sorted order)
    real(rp), allocatable :: ax(:), az(:), ar(:), xu(:), xw(:)
    ! one pair list per thread, and the kept pairs of each row (traversal.f90)
    type(pair_list_t), allocatable :: lists(:), cache(:)
    ! the neighbour list: pairs of each row task (rows(0:grid%ncz-1)), build positions
    ! (particle order), and what the build saw
    type(row_list_t), allocatable :: rows(:)
    real(rp), allocatable :: xb(:), zb(:)
    logical :: built = .false.
    integer :: n_all = -1, n_active = -1
    integer :: n_builds = 0                !< builds so far (diagnostics)
    real(rp) :: skin_per_h = SKIN_PER_H    !< 0: list exactly the pairs closer than 2h
    logical :: all_pairs = .false.         !< list boundary-boundary pairs too
  end type sorted_t

contains

  !> Gathers the fields of the active particles in sorted order, building the sorted order
  !> and the neighbour list first when they are missing or no longer cover the state.
  subroutine gather_sorted(st, h, s)
    type(state_t), intent(inout) :: st
    real(rp), intent(in) :: h
    type(sorted_t), intent(inout) :: s
    integer :: k, i, n, nact
    real(rp) :: skin, d2max
    logical :: valid

    skin = s%skin_per_h * h
    valid = s%built .and. s%n_all == st%n
    if (associated(st%list_x) .and. associated(st%list_z)) then
      ! the caller's build positions are the reference; ours may be of another run
      if (valid) valid = all(s%xb(1:st%n) == st%list_x) .and. all(s%zb(1:st%n) == st%list_z)
      if (.not. valid .and. listed_positions(st)) then
        call build(st, st%list_x, st%list_z, h, skin, s)
        valid = .true.
      end if
    end if
    if (valid) then
      nact = 0
      d2max = 0.0_rp
      !$omp parallel do schedule(static) reduction(+:nact) reduction(max:d2max)
      do i = 1, st%n
        if (st%active(i) == 0) cycle
        nact = nact + 1
        d2max = max(d2max, (st%x(i) - s%xb(i))**2 + (st%z(i) - s%zb(i))**2)
      end do
      !$omp end parallel do
      valid = nact == s%n_active .and. d2max <= (0.5_rp * skin)**2
    end if
    if (.not. valid) then
      call build(st, st%x, st%z, h, skin, s)
      if (associated(st%list_x) .and. associated(st%list_z)) then
        st%list_x = st%x
        st%list_z = st%z
      end if
    end if

    n = s%n
    !$omp parallel do schedule(static) private(i)
    do k = 1, n
      i = s%grid%order(k)
      s%x(k) = st%x(i)
      s%z(k) = st%z(i)
      s%u(k) = st%u(i)
      s%w(k) = st%w(i)
      s%rho(k) = st%rho(i)
      s%p(k) = st%p(i)
      s%c(k) = st%c(i)
      s%m(k) = st%m(i)
      s%pr(k) = st%p(i) / (st%rho(i) * st%rho(i))
      s%fluid(k) = st%kind(i) == KIND_FLUID
      s%ax(k) = 0.0_rp
      s%az(k) = 0.0_rp
      s%ar(k) = 0.0_rp
      s%xu(k) = 0.0_rp
      s%xw(k) = 0.0_rp
    end do
    !$omp end parallel do
  end subroutine gather_sorted

  !> Whether the caller's build positions are usable: finite for every active particle.
  logical function listed_positions(st)
    type(state_t), intent(in) :: st
    integer :: i
    listed_positions = .true.
    do i = 1, st%n
      if (st%active(i) == 0) cycle
      if (ieee_is_finite(st%list_x(i)) .and. ieee_is_finite(st%list_z(i))) cycle
      listed_positions = .false.
      return
    end do
  end function listed_positions

  !> Sorts the active particles by cell of side 2h + skin at the positions xl, zl and lists
  !> their pairs closer than 2h + skin there; keeps xl, zl as the build positions.
  subroutine build(st, xl, zl, h, skin, s)
    type(state_t), intent(in) :: st
    real(rp), intent(in) :: xl(:), zl(:), h, skin
    type(sorted_t), intent(inout) :: s
    integer :: k, i, n
    real(rp) :: cut

    cut = 2.0_rp * h + skin
    call build_cell_list(xl, zl, st%active, cut, s%grid)
    n = s%grid%nsorted
    s%n = n
    call ensure(s, n, st%n)
    s%xb(1:st%n) = xl
    s%zb(1:st%n) = zl
    s%n_all = st%n
    s%n_active = n
    s%built = .true.
    s%n_builds = s%n_builds + 1
    call thread_lists(s)
    if (allocated(s%rows)) then
      if (size(s%rows) < s%grid%ncz) deallocate(s%rows)
    end if
    if (.not. allocated(s%rows)) allocate(s%rows(0:s%grid%ncz - 1))
    ! the build positions in sorted order (s%x, s%z are gathered again afterwards)
    do k = 1, n
      i = s%grid%order(k)
      s%x(k) = xl(i)
      s%z(k) = zl(i)
      s%fluid(k) = st%kind(i) == KIND_FLUID
    end do
    call build_verlet_rows(s%grid, s%x(1:n), s%z(1:n), s%fluid(1:n), cut * cut, s%all_pairs, &
                           s%lists, s%rows)
  end subroutine build

  !> One pair list per thread (at least omp_get_max_threads()), kept in the work space from
  !> sweep to sweep.
  subroutine thread_lists(s)
    type(sorted_t), intent(inout) :: s
    integer :: nt
    nt = 1
    !$ nt = omp_get_max_threads()
    if (allocated(s%lists)) then
      if (size(s%lists) < nt) deallocate(s%lists)
    end if
    if (.not. allocated(s%lists)) allocate(s%lists(nt))
  end subroutine thread_lists

  subroutine ensure(s, n, n_all)
    type(sorted_t), intent(inout) :: s
    integer, intent(in) :: n, n_all
    if (allocated(s%xb)) then
      if (size(s%xb) < n_all) deallocate(s%xb, s%zb)
    end if
    if (.not. allocated(s%xb)) allocate(s%xb(n_all), s%zb(n_all))
    if (allocated(s%x)) then
      if (size(s%x) >= n) return
      deallocate(s%x, s%z, s%u, s%w, s%rho, s%p, s%c, s%m, s%pr, s%fluid, &
                 s%ax, s%az, s%ar, s%xu, s%xw)
    end if
    allocate(s%x(n), s%z(n), s%u(n), s%w(n), s%rho(n), s%p(n), s%c(n), s%m(n), s%pr(n), &
             s%fluid(n), s%ax(n), s%az(n), s%ar(n), s%xu(n), s%xw(n))
  end subroutine ensure

end module sorted_state
