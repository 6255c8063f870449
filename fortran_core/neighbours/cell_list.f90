!> Linked-list cell search, as a counting sort: cells of side 2h (the kernel support) laid over
!> the bounding box of the active particles; particles are ordered by cell (row by row, z rows
!> of x cells) so that every cell is one contiguous range of the sorted order.
module cell_list
  use sphjet_kinds, only: rp, ip
  implicit none
  private
  public :: cell_grid_t, build_cell_list

  type :: cell_grid_t
    integer :: ncx = 0, ncz = 0
    real(rp) :: xmin = 0.0_rp, zmin = 0.0_rp, cell = 1.0_rp
    integer :: nsorted = 0
    integer, allocatable :: start(:)   !< start(c) .. start(c+1)-1 = sorted slots of cell c (1-based)
    integer, allocatable :: order(:)   !< order(k) = particle index in slot k
  end type cell_grid_t

contains

  !> Sorts the active particles (active /= 0) into cells of side cell_size.
  subroutine build_cell_list(x, z, active, cell_size, grid)
    real(rp), intent(in) :: x(:), z(:)
    integer(ip), intent(in) :: active(:)
    real(rp), intent(in) :: cell_size
    type(cell_grid_t), intent(inout) :: grid
    integer :: i, c, n, ncell, nact
    real(rp) :: xmin, xmax, zmin, zmax, inv
    integer, allocatable :: cell_of(:), fill(:)

    n = size(x)
    xmin = huge(1.0_rp); xmax = -huge(1.0_rp)
    zmin = huge(1.0_rp); zmax = -huge(1.0_rp)
    nact = 0
    do i = 1, n
      if (active(i) == 0) cycle
      nact = nact + 1
      xmin = min(xmin, x(i)); xmax = max(xmax, x(i))
      zmin = min(zmin, z(i)); zmax = max(zmax, z(i))
    end do
    if (nact == 0) then
      xmin = 0.0_rp; xmax = 0.0_rp; zmin = 0.0_rp; zmax = 0.0_rp
    end if
    inv = 1.0_rp / cell_size
    grid%cell = cell_size
    grid%xmin = xmin
    grid%zmin = zmin
    grid%ncx = int((xmax - xmin) * inv) + 1
    grid%ncz = int((zmax - zmin) * inv) + 1
    ncell = grid%ncx * grid%ncz
    grid%nsorted = nact

    if (allocated(grid%start)) then
      if (size(grid%start) < ncell + 1) deallocate(grid%start)
    end if
    if (.not. allocated(grid%start)) allocate(grid%start(ncell + 1))
    if (allocated(grid%order)) then
      if (size(grid%order) < n) deallocate(grid%order)
    end if
    if (.not. allocated(grid%order)) allocate(grid%order(n))
    allocate(cell_of(n), fill(ncell + 1))

    fill = 0
    do i = 1, n
      if (active(i) == 0) then
        cell_of(i) = 0
        cycle
      end if
      c = 1 + min(int((x(i) - xmin) * inv), grid%ncx - 1) &
            + grid%ncx * min(int((z(i) - zmin) * inv), grid%ncz - 1)
      cell_of(i) = c
      fill(c) = fill(c) + 1
    end do
    grid%start(1) = 1
    do c = 1, ncell
      grid%start(c + 1) = grid%start(c) + fill(c)
    end do
    fill(1:ncell) = grid%start(1:ncell)
    do i = 1, n
      c = cell_of(i)
      if (c == 0) cycle
      grid%order(fill(c)) = i
      fill(c) = fill(c) + 1
    end do
  end subroutine build_cell_list

end module cell_list
