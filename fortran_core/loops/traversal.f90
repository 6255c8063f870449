!> The one pair traversal every pair loop uses (rates, density filters, surface tension, the
!> neighbour search of the C API). Each unordered pair of particles closer than 2h is visited
!> once: a cell meets itself and its east, north-west, north and north-east neighbours.
!>
!> Work is split into row tasks. A task first gathers the pairs of its row that are within
!> the kernel support into a compact list (pair_list_t: indices, separation, r^2 and, once
!> for the whole list with the kernel chosen outside the loop, W and F); the loop body
!> (pair_body_t%visit) then does branch-free arithmetic over that list. A task on row r
!> writes only rows r and r+1, so tasks on rows of one parity never touch the same particle
!> and run in parallel without atomics (two phases: even rows, then odd rows, in one
!> parallel region). Every particle therefore receives its contributions in a fixed order,
!> whatever the thread count: results are bitwise independent of the number of threads.
!>
!> A new pair loop is a type extending pair_body_t whose visit calls pure pair formulas
!> from physics/ over the list; pair_sweep does the rest.
module traversal
  use sphjet_kinds, only: rp
  use sphjet_kernels, only: kernel_t, kernel_eval_list
  use sorted_state, only: sorted_t
  use pair_list, only: pair_list_t, reserve
  !$ use omp_lib, only: omp_get_max_threads, omp_get_thread_num
  implicit none
  private
  public :: pair_list_t, pair_body_t, pair_sweep, build_row_pairs, &
            PAIRS_ALL, PAIRS_ANY_FLUID, PAIRS_FLUID

  !> Which pairs a sweep visits.
  integer, parameter :: PAIRS_ALL = 0        !< every active pair closer than 2h (no kernel)
  integer, parameter :: PAIRS_ANY_FLUID = 1  !< at least one fluid particle, r > 0
  integer, parameter :: PAIRS_FLUID = 2      !< both fluid, r > 0

  !> Coincident particles (r^2 at most this) exert no pair force.
  real(rp), parameter :: R2_MIN = 1.0e-18_rp

  !> A pair loop body: visit accumulates the contributions of the pairs of one row task.
  !> It may write only the entries of particles in pl%a and pl%b; red is a running max
  !> reduced over the tasks.
  type, abstract :: pair_body_t
  contains
    procedure(visit_i), deferred :: visit
  end type pair_body_t

  abstract interface
    subroutine visit_i(self, pl, red)
      import :: pair_body_t, pair_list_t, rp
      class(pair_body_t), intent(inout) :: self
      type(pair_list_t), intent(inout) :: pl
      real(rp), intent(inout) :: red
    end subroutine visit_i
  end interface

contains

  !> Visits every pair of `mode` of the sorted particles with `body`: one parallel region,
  !> two phases of row tasks. red: max over the tasks of what visit leaves in it.
  subroutine pair_sweep(s, kern, mode, body, red)
    type(sorted_t), intent(inout) :: s
    type(kernel_t), intent(in) :: kern
    integer, intent(in) :: mode
    class(pair_body_t), intent(inout) :: body
    real(rp), intent(inout) :: red
    integer :: nt
    ! one pair list per thread, kept in the work space from sweep to sweep
    nt = 1
    !$ nt = omp_get_max_threads()
    if (allocated(s%lists)) then
      if (size(s%lists) < nt) deallocate(s%lists)
    end if
    if (.not. allocated(s%lists)) allocate(s%lists(nt))
    !$omp parallel reduction(max:red)
    call sweep_thread(s, kern, mode, body, red)
    !$omp end parallel
  end subroutine pair_sweep

  !> One thread's share of a sweep, with the thread's own pair list.
  subroutine sweep_thread(s, kern, mode, body, red)
    type(sorted_t), intent(inout), target :: s
    type(kernel_t), intent(in) :: kern
    integer, intent(in) :: mode
    class(pair_body_t), intent(inout) :: body
    real(rp), intent(inout) :: red
    type(pair_list_t), pointer :: pl
    integer :: phase, row, me
    me = 1
    !$ me = omp_get_thread_num() + 1
    pl => s%lists(me)
    do phase = 0, 1
      !$omp do schedule(dynamic, 1)
      do row = phase, s%grid%ncz - 1, 2
        call build_row_pairs(s, row, kern%support2, mode, pl)
        if (mode /= PAIRS_ALL) call kernel_eval_list(kern, pl%r2(1:pl%n), pl%w(1:pl%n), pl%f(1:pl%n))
        call body%visit(pl, red)
      end do
      !$omp end do
    end do
  end subroutine sweep_thread

  !> The pairs of row task `row` (0-based) closer than sqrt(support2) into pl, in the order
  !> cell (west to east), partner cell (self, E, NW, N, NE), a, b.
  subroutine build_row_pairs(s, row, support2, mode, pl)
    type(sorted_t), intent(in) :: s
    integer, intent(in) :: row, mode
    real(rp), intent(in) :: support2
    type(pair_list_t), intent(inout) :: pl
    integer :: cx, c, ncx, ncz, m
    ncx = s%grid%ncx
    ncz = s%grid%ncz
    ! room for every candidate of the row: each particle with its own and the four next cells
    m = 0
    do cx = 0, ncx - 1
      c = 1 + cx + ncx * row
      m = m + count_in(c) * (count_in(c) + count_in(c + 1) + merge(count_in(c + ncx - 1) &
          + count_in(c + ncx) + count_in(c + ncx + 1), 0, row + 1 < ncz))
    end do
    call reserve(pl, m)
    do cx = 0, ncx - 1
      c = 1 + cx + ncx * row
      if (s%grid%start(c + 1) <= s%grid%start(c)) cycle
      call cell_pair(c, .true.)
      if (cx + 1 < ncx) call cell_pair(c + 1, .false.)
      if (row + 1 < ncz) then
        if (cx > 0) call cell_pair(c + ncx - 1, .false.)
        call cell_pair(c + ncx, .false.)
        if (cx + 1 < ncx) call cell_pair(c + ncx + 1, .false.)
      end if
    end do

  contains

    subroutine cell_pair(cb, self)
      integer, intent(in) :: cb
      logical, intent(in) :: self
      integer :: a, b0, b1
      logical :: fa
      b1 = s%grid%start(cb + 1) - 1
      do a = s%grid%start(c), s%grid%start(c + 1) - 1
        b0 = merge(a + 1, s%grid%start(cb), self)
        if (b1 < b0) cycle
        fa = s%fluid(a)
        if (mode == PAIRS_FLUID .and. .not. fa) cycle
        call keep_close(a, b0, b1, s%x, s%z, s%fluid, support2, &
                        merge(-1.0_rp, R2_MIN, mode == PAIRS_ALL), &
                        mode == PAIRS_FLUID .or. (mode == PAIRS_ANY_FLUID .and. .not. fa), &
                        pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%r2, pl%mixed)
      end do
    end subroutine cell_pair

    !> Particles in cell cc (0 for a cell index beyond the grid).
    pure integer function count_in(cc)
      integer, intent(in) :: cc
      if (cc > ncx * ncz) then
        count_in = 0
      else
        count_in = s%grid%start(cc + 1) - s%grid%start(cc)
      end if
    end function count_in

  end subroutine build_row_pairs

  !> Appends the pairs (a, b), b = b0..b1, with lo2 < r^2 < support2 (and b fluid when
  !> need_fluid) at n+1...: every candidate is written and kept by advancing n, so that the
  !> loop has no data-dependent branch. The arrays must have room for n + b1 - b0 + 1.
  pure subroutine keep_close(a, b0, b1, x, z, fluid, support2, lo2, need_fluid, n, pa, pb, &
                             pdx, pdz, pr2, mixed)
    integer, intent(in) :: a, b0, b1
    real(rp), intent(in) :: x(:), z(:), support2, lo2
    logical, intent(in) :: fluid(:), need_fluid
    integer, intent(inout) :: n
    integer, intent(inout) :: pa(:), pb(:)
    real(rp), intent(inout) :: pdx(:), pdz(:), pr2(:)
    logical, intent(inout) :: mixed(:)
    integer :: b, k
    real(rp) :: xa, za, dx, dz, r2
    logical :: fa, keep, nf
    xa = x(a)
    za = z(a)
    fa = fluid(a)
    nf = .not. need_fluid
    k = n
    do b = b0, b1
      dx = xa - x(b)
      dz = za - z(b)
      r2 = dx * dx + dz * dz
      ! products of 0/1, not .and.: the compiler would branch on each operand
      keep = merge(1, 0, r2 < support2) * merge(1, 0, r2 > lo2) * merge(1, 0, fluid(b) .or. nf) /= 0
      pa(k + 1) = a
      pb(k + 1) = b
      pdx(k + 1) = dx
      pdz(k + 1) = dz
      pr2(k + 1) = r2
      mixed(k + 1) = fa .neqv. fluid(b)
      k = k + merge(1, 0, keep)
    end do
    n = k
  end subroutine keep_close


end module traversal
