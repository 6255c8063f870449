!> The compact pair list of one row task (loops/traversal.f90): the pairs within the kernel
!> support, their separation, W and F, and scratch columns for the loop body. One list per
!> thread lives in the work space (sorted_t, loops/sorted_state.f90) so that it is allocated
!> once, not every sweep; a list build (verlet_list.f90) uses them for its candidate pairs.
module pair_list
  use sphjet_kinds, only: rp
  implicit none
  private
  public :: pair_list_t, reserve

  !> Scratch columns per pair available to a loop body.
  integer, parameter :: N_SCRATCH = 6

  !> The pairs of one row task, in traversal order (a < b in sorted slots).
  type :: pair_list_t
    integer :: n = 0
    integer, allocatable :: a(:), b(:)
    real(rp), allocatable :: dx(:), dz(:), r2(:)   !< r_a - r_b and its square
    real(rp), allocatable :: w(:), f(:)            !< W_ab and F_ab = (dW/dr)/r
    logical, allocatable :: mixed(:)               !< one fluid, one boundary particle
    real(rp), allocatable :: t(:, :)               !< scratch (pair, column) for the body
  end type pair_list_t

contains

  !> Room for at least m pairs in pl; the list is emptied. scratch (default .true.): with the
  !> scratch columns pl%t.
  subroutine reserve(pl, m, scratch)
    type(pair_list_t), intent(inout) :: pl
    integer, intent(in) :: m
    logical, intent(in), optional :: scratch
    integer :: cap
    logical :: with_t
    with_t = .true.
    if (present(scratch)) with_t = scratch
    pl%n = 0
    if (allocated(pl%a)) then
      if (size(pl%a) < m) then
        deallocate(pl%a, pl%b, pl%dx, pl%dz, pl%r2, pl%w, pl%f, pl%mixed)
        if (allocated(pl%t)) deallocate(pl%t)
      end if
    end if
    if (.not. allocated(pl%a)) then
      cap = max(1024, m + m / 2)
      allocate(pl%a(cap), pl%b(cap), pl%dx(cap), pl%dz(cap), pl%r2(cap), pl%w(cap), pl%f(cap), &
               pl%mixed(cap))
    end if
    if (with_t .and. .not. allocated(pl%t)) allocate(pl%t(size(pl%a), N_SCRATCH))
  end subroutine reserve

end module pair_list
