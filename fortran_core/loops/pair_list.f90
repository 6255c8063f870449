!> The compact pair list of one row task (traversal.f90): the pairs within the kernel
!> support, their separation, W and F, and scratch columns for the loop body. One list per
!> thread lives in the work space (sorted_t) so that it is allocated once, not every sweep.
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

  !> Room for at least m pairs in pl (contents kept).
  subroutine reserve(pl, m)
    type(pair_list_t), intent(inout) :: pl
    integer, intent(in) :: m
    integer :: cap
    if (allocated(pl%a)) then
      if (size(pl%a) >= m) return
    end if
    cap = max(1024, 2 * m)
    call grow_i(pl%a); call grow_i(pl%b)
    call grow_r(pl%dx); call grow_r(pl%dz); call grow_r(pl%r2)
    call grow_r(pl%w); call grow_r(pl%f)
    call grow_l(pl%mixed)
    if (allocated(pl%t)) deallocate(pl%t)
    allocate(pl%t(cap, N_SCRATCH))

  contains

    subroutine grow_i(v)
      integer, allocatable, intent(inout) :: v(:)
      integer, allocatable :: tmp(:)
      allocate(tmp(cap))
      if (allocated(v)) tmp(1:pl%n) = v(1:pl%n)
      call move_alloc(tmp, v)
    end subroutine grow_i

    subroutine grow_r(v)
      real(rp), allocatable, intent(inout) :: v(:)
      real(rp), allocatable :: tmp(:)
      allocate(tmp(cap))
      if (allocated(v)) tmp(1:pl%n) = v(1:pl%n)
      call move_alloc(tmp, v)
    end subroutine grow_r

    subroutine grow_l(v)
      logical, allocatable, intent(inout) :: v(:)
      logical, allocatable :: tmp(:)
      allocate(tmp(cap))
      if (allocated(v)) tmp(1:pl%n) = v(1:pl%n)
      call move_alloc(tmp, v)
    end subroutine grow_l

  end subroutine reserve

end module pair_list
