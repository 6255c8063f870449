!> The active particles gathered in cell order (contiguous per cell), the layout every pair
!> traversal works on; rates are accumulated here and scattered back afterwards.
module sorted_state
  use sphjet_kinds, only: rp, ip, KIND_FLUID
  use sphjet_types, only: state_t
  use cell_list, only: cell_grid_t, build_cell_list
  use pair_list, only: pair_list_t
  implicit none
  private
  public :: sorted_t, gather_sorted

  type :: sorted_t
    integer :: n = 0
    type(cell_grid_t) :: grid
    real(rp), allocatable :: x(:), z(:), u(:), w(:), rho(:), p(:), c(:), m(:), pr(:)
    logical, allocatable :: fluid(:)
    ! accumulated rates (sorted order)
    real(rp), allocatable :: ax(:), az(:), ar(:), xu(:), xw(:)
    ! one pair list per thread (traversal.f90)
    type(pair_list_t), allocatable :: lists(:)
  end type sorted_t

contains

  !> Builds the cell list over the active particles and gathers their fields.
  subroutine gather_sorted(st, h, s)
    type(state_t), intent(in) :: st
    real(rp), intent(in) :: h
    type(sorted_t), intent(inout) :: s
    integer :: k, i, n

    call build_cell_list(st%x, st%z, st%active, 2.0_rp * h, s%grid)
    n = s%grid%nsorted
    s%n = n
    call ensure(s, n)
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

  subroutine ensure(s, n)
    type(sorted_t), intent(inout) :: s
    integer, intent(in) :: n
    if (allocated(s%x)) then
      if (size(s%x) >= n) return
      deallocate(s%x, s%z, s%u, s%w, s%rho, s%p, s%c, s%m, s%pr, s%fluid, &
                 s%ax, s%az, s%ar, s%xu, s%xw)
    end if
    allocate(s%x(n), s%z(n), s%u(n), s%w(n), s%rho(n), s%p(n), s%c(n), s%m(n), s%pr(n), &
             s%fluid(n), s%ax(n), s%az(n), s%ar(n), s%xu(n), s%xw(n))
  end subroutine ensure

end module sorted_state
