!> The one pair traversal every pair loop uses (rates, density filters, surface tension, the
!> neighbour search of the C API). Each unordered pair of particles closer than 2h is visited
!> once: the neighbour list of list_rebuild.f90 (neighbours/verlet_list.f90) holds, per row
!> of cells, the pairs that were closer than 2h + skin at its build (a cell with itself and
!> its east, north-west, north and north-east neighbours), and stays valid over several steps.
!>
!> Work is split into row tasks. A task first keeps the listed pairs of its row that are within
!> the kernel support now in a compact list (pair_list_t: indices, separation, r^2 and, once
!> for the whole list with the kernel chosen outside the loop, W and F); the loop body
!> (pair_body_t%visit) then does branch-free arithmetic over that list. A task on row r
!> writes only rows r and r+1, so tasks on rows of one parity never touch the same particle
!> and run in parallel without atomics on the sums. Each thread of a team owns a contiguous
!> block of rows holding about its share of the listed pairs (block_start) and runs its even
!> rows, then its odd ones, taking what is left of the other blocks' rows of that parity
!> from their tops once its own are done; a task on odd row r starts once the tasks on even
!> rows r - 1 and r + 1 have finished (sweep_thread; no barrier between the two halves).
!> Every particle therefore receives its contributions in a fixed order, whatever the
!> thread count: results are bitwise independent of the number of threads.
!>
!> A new pair loop is a type extending pair_body_t whose visit calls pure pair formulas
!> from physics/ over the list; pair_sweep does the rest.
module traversal
  use sphjet_kinds, only: rp
  use sphjet_kernels, only: kernel_t, kernel_eval_list
  use sorted_state, only: sorted_t, thread_lists
  use omp_team, only: one_thread, in_open_team
  use pair_list, only: pair_list_t, reserve
  !$ use omp_lib, only: omp_get_thread_num, omp_get_num_threads
  implicit none
  private
  public :: pair_list_t, pair_body_t, pair_sweep, build_row_pairs, &
            PAIRS_ALL, PAIRS_ANY_FLUID, PAIRS_FLUID, SWEEP_FRESH, SWEEP_KEEP, SWEEP_REUSE

  !> Which pairs a sweep visits.
  integer, parameter :: PAIRS_ALL = 0        !< every active pair closer than 2h (no kernel)
  integer, parameter :: PAIRS_ANY_FLUID = 1  !< at least one fluid particle, r > 0
  integer, parameter :: PAIRS_FLUID = 2      !< both fluid, r > 0

  !> What a sweep does with the kernel-support pairs it keeps (pair_sweep's `cache`).
  integer, parameter :: SWEEP_FRESH = 0  !< keep them in the thread's list, for this sweep only
  integer, parameter :: SWEEP_KEEP = 1   !< keep them per row in the work space (s%cache)
  integer, parameter :: SWEEP_REUSE = 2  !< visit the pairs (and W, F) the last SWEEP_KEEP kept:
                                         !< same mode, positions unchanged since then

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

  !> Visits every pair of `mode` of the sorted particles with `body`: one parallel region of
  !> row tasks. red: max over the tasks of what visit leaves in it. s must
  !> hold the gathered state and its neighbour list (gather_sorted). cache (SWEEP_*, default
  !> SWEEP_FRESH): a series of sweeps over the same positions (the CSF passes, the two MLS
  !> passes) finds the pairs and evaluates the kernel once (SWEEP_KEEP, then SWEEP_REUSE).
  !> Kept lists have no scratch columns (pl%t): their bodies must not use them.
  subroutine pair_sweep(s, kern, mode, body, red, cache)
    type(sorted_t), intent(inout) :: s
    type(kernel_t), intent(in) :: kern
    integer, intent(in) :: mode
    class(pair_body_t), intent(inout) :: body
    real(rp), intent(inout) :: red
    integer, intent(in), optional :: cache
    integer :: how
    how = SWEEP_FRESH
    if (present(cache)) how = cache
    if (in_open_team()) then
      ! every thread of an open team (omp_team.f90): the thread lists were made before
      ! the team opened (pc_step); kept lists are not made here (pc_step opens no team with
      ! surface tension, whose sweeps keep them)
      call sweep_thread(s, kern, mode, how, body, red)
      return
    end if
    call thread_lists(s)
    if (how == SWEEP_KEEP) then
      if (allocated(s%cache)) then
        if (size(s%cache) < s%grid%ncz) deallocate(s%cache)
      end if
      if (.not. allocated(s%cache)) allocate(s%cache(0:s%grid%ncz - 1))
    end if
    if (one_thread()) then
      call sweep_thread(s, kern, mode, how, body, red)
    else
      !$omp parallel
      call sweep_thread(s, kern, mode, how, body, red)
      !$omp end parallel
    end if
  end subroutine pair_sweep

  !> One thread's share of a sweep, with the thread's own pair list (or the kept ones); red
  !> is shared by the team. Alone, a thread runs the even rows, then the odd ones. In a team,
  !> each thread runs its block's even rows (block_start), then those left in the other blocks,
  !> then the odd rows likewise (claim). A task on odd row r writes rows r and r + 1, which
  !> the tasks on the even rows r - 1 and r + 1 also write: it starts when those two have
  !> finished (not when every even row has, as a barrier between two phases would have it).
  !> Each particle thus receives its contributions in the same order, whatever the thread
  !> count and whichever thread runs a row.
  subroutine sweep_thread(s, kern, mode, how, body, red)
    type(sorted_t), intent(inout), target :: s
    type(kernel_t), intent(in) :: kern
    integer, intent(in) :: mode, how
    class(pair_body_t), intent(inout) :: body
    real(rp), intent(inout) :: red
    type(pair_list_t), pointer :: pl
    integer :: row, me, nt, ncz, done, parity, v, victim, out, k
    integer, allocatable :: starts(:)
    real(rp) :: mine
    me = 1
    nt = 1
    !$ me = omp_get_thread_num() + 1
    !$ nt = omp_get_num_threads()
    pl => s%lists(me)
    ncz = s%grid%ncz
    mine = -huge(1.0_rp)   ! this thread's max; red is read only where it is merged
    if (nt == 1) then   ! the rows' counts stay as they are (all equal)
      do row = 0, ncz - 1, 2
        call visit_row(row)
      end do
      do row = 1, ncz - 1, 2
        call visit_row(row)
      end do
      red = max(red, mine)
      return
    end if
    ! the count every row reaches in this sweep: the sweeps so far plus one (sweeps is moved
    ! on by the last thread out, after every thread has read it here)
    !$omp atomic read
    done = s%sweeps
    !$omp end atomic
    done = done + 1
    ! the threads' blocks: block b is rows starts(b - 1) .. starts(b) - 1
    allocate(starts(0:nt))
    do k = 0, nt
      starts(k) = block_start(s, k, nt)
    end do
    ! the even rows, then the odd ones: first those of this thread's block, upwards, then
    ! any left in the other blocks, taken from their top ends
    do parity = 0, 1
      do v = 0, nt - 1
        victim = modulo(me - 1 + v, nt) + 1
        do
          call claim(victim, parity, v == 0, row)
          if (row < 0) exit
          if (parity == 1) then
            call wait_row(row - 1)
            if (row + 1 < ncz) call wait_row(row + 1)
          end if
          call visit_row(row)
          !$omp flush
          !$omp atomic write
          s%row_done(row) = done
        end do
      end do
    end do
    ! the last thread out readies the claims for the next sweep
    !$omp atomic capture
    s%threads_out = s%threads_out + 1
    out = s%threads_out
    !$omp end atomic
    if (out == nt) then
      s%claims(:, 1:nt) = 0
      s%threads_out = 0
      !$omp atomic write
      s%sweeps = done
    end if
    !$omp critical (sweep_max)
    red = max(red, mine)
    !$omp end critical (sweep_max)
    !$omp barrier
  contains
    !> The next row of parity par in block b (starts) not yet taken this sweep, from the
    !> block's bottom (its own thread) or its top (another thread); -1 if none is left. Both
    !> ends are counted in one word, bottom in the low half, top in the high half, and a
    !> taker adds one to its half in a single atomic step: the values it sees before its add
    !> say whether a row was left and which one is its.
    subroutine claim(b, par, own, r)
      integer, intent(in) :: b, par
      logical, intent(in) :: own
      integer, intent(out) :: r
      integer(8), parameter :: TOP = 2_8**32
      integer(8) :: was, add
      integer :: first, n, n_bottom, n_top
      first = starts(b - 1) + modulo(par - starts(b - 1), 2)
      n = 0
      if (first < starts(b)) n = (starts(b) - 1 - first) / 2 + 1
      r = -1
      if (n == 0) return
      add = merge(1_8, TOP, own)
      !$omp atomic capture
      was = s%claims(par, b)
      s%claims(par, b) = s%claims(par, b) + add
      !$omp end atomic
      n_bottom = int(iand(was, TOP - 1))
      n_top = int(ishft(was, -32))
      if (n_bottom + n_top >= n) return
      if (own) then
        r = first + 2 * n_bottom
      else
        r = first + 2 * (n - 1 - n_top)
      end if
    end subroutine claim
    subroutine visit_row(r)
      integer, intent(in) :: r
      if (how /= SWEEP_FRESH) pl => s%cache(r)
      if (how /= SWEEP_REUSE) then
        call build_row_pairs(s, r, kern%support2, mode, pl, how == SWEEP_FRESH)
        if (mode /= PAIRS_ALL) call kernel_eval_list(kern, pl%r2(1:pl%n), pl%w(1:pl%n), pl%f(1:pl%n))
      end if
      call body%visit(pl, mine)
    end subroutine visit_row
    !> Waits until row r has finished this sweep's task (its count reached done).
    subroutine wait_row(r)
      integer, intent(in) :: r
      integer :: d
      do
        !$omp atomic read
        d = s%row_done(r)
        if (d >= done) exit
      end do
      !$omp flush
    end subroutine wait_row
  end subroutine sweep_thread

  !> The first row of block k of nt in a team's sweep (0 for k = 0, ncz for k = nt): the
  !> first row whose listed pairs start at or beyond k/nt of all of them (s%row_cum), so that
  !> each block holds about 1/nt of the pairs. Contiguous blocks keep each thread on its own
  !> particles from sweep to sweep, in its own core's cache: with rows handed out one at a
  !> time, a row's particles went to either thread in turn, and two threads spent 1.7 times
  !> one thread's cpu time.
  pure integer function block_start(s, k, nt) result(r)
    type(sorted_t), intent(in) :: s
    integer, intent(in) :: k, nt
    integer(8) :: b
    integer :: l, u, m, ncz
    ncz = s%grid%ncz
    if (k <= 0) then
      r = 0
      return
    end if
    if (k >= nt) then
      r = ncz
      return
    end if
    b = (int(s%row_cum(ncz), 8) * k + nt - 1) / nt
    l = 0
    u = ncz
    do while (l < u)   ! row_cum is non-decreasing: bisect for the first row_cum >= b
      m = (l + u) / 2
      if (int(s%row_cum(m), 8) >= b) then
        u = m
      else
        l = m + 1
      end if
    end do
    r = l
  end function block_start

  !> The pairs of row task `row` (0-based) closer than sqrt(support2) now into pl: the
  !> row's neighbour list (list_rebuild.f90) filtered, in its order (cell west to east, a,
  !> partner cell self, E, NW, N, NE, b).
  subroutine build_row_pairs(s, row, support2, mode, pl, scratch)
    type(sorted_t), intent(in) :: s
    integer, intent(in) :: row, mode
    real(rp), intent(in) :: support2
    type(pair_list_t), intent(inout) :: pl
    logical, intent(in), optional :: scratch   !< with pl%t (default)
    associate (rl => s%rows(row))
      call reserve(pl, rl%n, scratch)
      call keep_close(rl%n, rl%a, rl%b, s%x, s%z, s%fluid, support2, &
                      merge(-1.0_rp, R2_MIN, mode == PAIRS_ALL), mode == PAIRS_FLUID, &
                      mode == PAIRS_ANY_FLUID, pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%r2, pl%mixed)
    end associate
  end subroutine build_row_pairs

  !> Appends the listed pairs (la(j), lb(j)), j = 1..nl, with lo2 < r^2 < support2 (both
  !> fluid when both_fluid, one of them when one_fluid) at n+1...: every pair is written and
  !> kept by advancing n, so that the loop has no data-dependent branch. The arrays must have
  !> room for n + nl.
  pure subroutine keep_close(nl, la, lb, x, z, fluid, support2, lo2, both_fluid, one_fluid, &
                             n, pa, pb, pdx, pdz, pr2, mixed)
    integer, intent(in) :: nl, la(:), lb(:)
    real(rp), intent(in) :: x(:), z(:), support2, lo2
    logical, intent(in) :: fluid(:), both_fluid, one_fluid
    integer, intent(inout) :: n
    integer, intent(inout) :: pa(:), pb(:)
    real(rp), intent(inout) :: pdx(:), pdz(:), pr2(:)
    logical, intent(inout) :: mixed(:)
    integer :: j, k, a, b
    real(rp) :: dx, dz, r2
    logical :: fa, fb, nb, no
    nb = .not. both_fluid
    no = .not. one_fluid
    k = n
    do j = 1, nl
      a = la(j)
      b = lb(j)
      dx = x(a) - x(b)
      dz = z(a) - z(b)
      r2 = dx * dx + dz * dz
      fa = fluid(a)
      fb = fluid(b)
      pa(k + 1) = a
      pb(k + 1) = b
      pdx(k + 1) = dx
      pdz(k + 1) = dz
      pr2(k + 1) = r2
      mixed(k + 1) = fa .neqv. fb
      ! products of 0/1, not .and.: the compiler would branch on each operand
      k = k + merge(1, 0, r2 < support2) * merge(1, 0, r2 > lo2) &
            * merge(1, 0, (fa .and. fb) .or. nb) * merge(1, 0, fa .or. fb .or. no)
    end do
    n = k
  end subroutine keep_close

end module traversal
