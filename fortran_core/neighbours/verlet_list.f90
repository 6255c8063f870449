!> Verlet (neighbour) lists with a skin, one per row of cells. At a build, the particles are
!> sorted into cells of side 2h + skin (cell_list.f90) and every pair closer than 2h + skin
!> (boundary-boundary pairs left out unless all pairs are asked for) is stored with its row
!> task: the row of cells of its first particle, in the order cell (west to east), a, partner
!> cell (self, E, NW, N, NE), b, with a and b sorted slots: all the listed pairs of a
!> particle a follow each other (one run of about 20 pairs, half its neighbours, where the
!> order cell, partner cell, a, b gave one run per partner cell; the rates loop carries a's
!> sums along its run: Case1 +5%, ObstW +0.5%, 1 thread). The pair sweeps
!> (loops/traversal.f90) then keep, at each evaluation, the listed pairs that are closer than
!> 2h now. The list stays exact as long as no particle has moved more than skin/2 from its
!> position at the build; loops/list_rebuild.f90 decides when to build it again.
module verlet_list
  use sphjet_kinds, only: rp
  use cell_list, only: cell_grid_t
  use pair_list, only: pair_list_t, reserve
  !$ use omp_lib, only: omp_get_thread_num
  implicit none
  private
  public :: row_list_t, build_verlet_rows

  !> The listed pairs of one row task (sorted slots at the build).
  type :: row_list_t
    integer :: n = 0
    integer, allocatable :: a(:), b(:)
  end type row_list_t

contains

  !> Lists of the rows 0 .. grid%ncz - 1 into rows(0:): the pairs closer than sqrt(cut2) of
  !> the sorted positions x, z (cells of side at least sqrt(cut2)), with at least one fluid
  !> particle unless all_pairs, and at least one real one (real: not an image slot, see
  !> loops/particle_images.f90: a pair of two images adds only to image sums, which are
  !> discarded). scratch: one pair list per thread (candidates of a row).
  subroutine build_verlet_rows(grid, x, z, fluid, real, cut2, all_pairs, scratch, rows, team)
    type(cell_grid_t), intent(in) :: grid
    real(rp), intent(in) :: x(:), z(:), cut2
    logical, intent(in) :: fluid(:), real(:), all_pairs
    type(pair_list_t), intent(inout), target :: scratch(:)
    type(row_list_t), intent(inout) :: rows(0:)
    logical, intent(in), optional :: team   !< called by every thread of a parallel region
    logical :: in_team
    in_team = .false.
    if (present(team)) in_team = team
    if (in_team) then
      call rows_of_this_thread()
    else
      !$omp parallel
      call rows_of_this_thread()
      !$omp end parallel
    end if
  contains
    subroutine rows_of_this_thread()
      integer :: row, me
      me = 1
      !$ me = omp_get_thread_num() + 1
      !$omp do schedule(dynamic, 1)
      do row = 0, grid%ncz - 1
        call build_row(grid, row, x, z, fluid, real, cut2, all_pairs, scratch(me), rows(row))
      end do
      !$omp end do
    end subroutine rows_of_this_thread
  end subroutine build_verlet_rows

  !> The list of one row: candidates of the cell stencil gathered into the scratch list, the
  !> kept ones copied into the row's own arrays (sized to what is kept, not to the candidates).
  subroutine build_row(grid, row, x, z, fluid, real, cut2, all_pairs, sc, rl)
    type(cell_grid_t), intent(in) :: grid
    integer, intent(in) :: row
    real(rp), intent(in) :: x(:), z(:), cut2
    logical, intent(in) :: fluid(:), real(:), all_pairs
    type(pair_list_t), intent(inout) :: sc
    type(row_list_t), intent(inout) :: rl
    integer :: cx, c, ncx, ncz, m, a
    ncx = grid%ncx
    ncz = grid%ncz
    ! room for every candidate of the row: each particle with its own and the four next cells
    m = 0
    do cx = 0, ncx - 1
      c = 1 + cx + ncx * row
      m = m + count_in(c) * (count_in(c) + count_in(c + 1) + merge(count_in(c + ncx - 1) &
          + count_in(c + ncx) + count_in(c + ncx + 1), 0, row + 1 < ncz))
    end do
    call reserve(sc, m)
    do cx = 0, ncx - 1
      c = 1 + cx + ncx * row
      do a = grid%start(c), grid%start(c + 1) - 1
        call with_cell(c, .true.)
        if (cx + 1 < ncx) call with_cell(c + 1, .false.)
        if (row + 1 < ncz) then
          if (cx > 0) call with_cell(c + ncx - 1, .false.)
          call with_cell(c + ncx, .false.)
          if (cx + 1 < ncx) call with_cell(c + ncx + 1, .false.)
        end if
      end do
    end do
    rl%n = sc%n
    if (allocated(rl%a)) then
      if (size(rl%a) < sc%n) deallocate(rl%a, rl%b)
    end if
    if (.not. allocated(rl%a)) allocate(rl%a(sc%n + sc%n / 8 + 16), rl%b(sc%n + sc%n / 8 + 16))
    rl%a(1:sc%n) = sc%a(1:sc%n)
    rl%b(1:sc%n) = sc%b(1:sc%n)

  contains

    !> The pairs of particle a with the particles of cell cb (after a in its own cell).
    subroutine with_cell(cb, self)
      integer, intent(in) :: cb
      logical, intent(in) :: self
      integer :: b0, b1
      b1 = grid%start(cb + 1) - 1
      b0 = merge(a + 1, grid%start(cb), self)
      if (b1 < b0) return
      call keep_within(a, b0, b1, x, z, fluid, real, cut2, all_pairs .or. fluid(a), real(a), &
                       sc%n, sc%a, sc%b)
    end subroutine with_cell

    !> Particles in cell cc (0 for a cell index beyond the grid).
    pure integer function count_in(cc)
      integer, intent(in) :: cc
      if (cc > ncx * ncz) then
        count_in = 0
      else
        count_in = grid%start(cc + 1) - grid%start(cc)
      end if
    end function count_in

  end subroutine build_row

  !> Appends the pairs (a, b), b = b0..b1, with r^2 < cut2 (and b fluid unless any_b, b real
  !> unless real_a) at n+1...: every candidate is written and kept by advancing n (no
  !> data-dependent branch).
  pure subroutine keep_within(a, b0, b1, x, z, fluid, real, cut2, any_b, real_a, n, pa, pb)
    integer, intent(in) :: a, b0, b1
    real(rp), intent(in) :: x(:), z(:), cut2
    logical, intent(in) :: fluid(:), real(:), any_b, real_a
    integer, intent(inout) :: n
    integer, intent(inout) :: pa(:), pb(:)
    integer :: b, k
    real(rp) :: xa, za, dx, dz
    xa = x(a)
    za = z(a)
    k = n
    do b = b0, b1
      dx = xa - x(b)
      dz = za - z(b)
      pa(k + 1) = a
      pb(k + 1) = b
      ! products of 0/1, not .and.: the compiler would branch on each operand
      k = k + merge(1, 0, dx * dx + dz * dz < cut2) * merge(1, 0, fluid(b) .or. any_b) &
            * merge(1, 0, real(b) .or. real_a)
    end do
    n = k
  end subroutine keep_within

end module verlet_list
