!> The one cell traversal every pair loop uses. Each unordered pair of particles closer than
!> the cell size is visited once: a cell meets itself and its east, north-west, north and
!> north-east neighbours. Work is split into row tasks; a task on row r writes only rows r
!> and r+1, so tasks on rows of one parity never touch the same particle and run in parallel
!> without atomics (two phases: even rows, then odd rows). Every particle therefore receives
!> its contributions in a fixed order, whatever the thread count: results are bitwise
!> independent of the number of threads.
module traversal
  use cell_list, only: cell_grid_t
  implicit none
  private
  public :: row_cell_pairs, MAX_PAIRS_PER_CELL

  integer, parameter :: MAX_PAIRS_PER_CELL = 5

contains

  !> Cell pairs of row task `row` (0-based): list(:, k) = [a_first, a_last, b_first, b_last, self]
  !> in sorted slots; self = 1 when a and b are the same cell (visit b > a only).
  subroutine row_cell_pairs(grid, row, list, count)
    type(cell_grid_t), intent(in) :: grid
    integer, intent(in) :: row
    integer, intent(out) :: list(:, :)
    integer, intent(out) :: count
    integer :: cx, c, a0, a1
    count = 0
    do cx = 0, grid%ncx - 1
      c = 1 + cx + grid%ncx * row
      a0 = grid%start(c)
      a1 = grid%start(c + 1) - 1
      if (a1 < a0) cycle
      call add(c, .true.)
      if (cx + 1 < grid%ncx) call add(c + 1, .false.)
      if (row + 1 < grid%ncz) then
        if (cx > 0) call add(c + grid%ncx - 1, .false.)
        call add(c + grid%ncx, .false.)
        if (cx + 1 < grid%ncx) call add(c + grid%ncx + 1, .false.)
      end if
    end do

  contains

    subroutine add(cb, self)
      integer, intent(in) :: cb
      logical, intent(in) :: self
      integer :: b0, b1
      b0 = grid%start(cb)
      b1 = grid%start(cb + 1) - 1
      if (b1 < b0) return
      count = count + 1
      list(:, count) = [a0, a1, b0, b1, merge(1, 0, self)]
    end subroutine add

  end subroutine row_cell_pairs

end module traversal
