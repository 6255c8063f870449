!> The OpenMP team machinery of the particle loops. A set of loops (team_work_t) runs in a
!> parallel region of its own, without a region when one thread is in use (one_thread), or
!> as the orphaned worksharing loops of a team that a caller has opened for several sets of
!> loops (set_open_team; integrate/predictor_corrector.f90: one parallel region per step).
module omp_team
  !$ use omp_lib, only: omp_get_max_threads, omp_in_parallel
  implicit none
  private
  public :: team_work_t, in_team, one_thread, in_open_team, set_open_team

  !> Whether this thread runs in a team that a caller has opened for several sets of loops
  !> (predictor_corrector.f90: one parallel region per step). Every thread of that team then
  !> calls in_team, gather_sorted, pair_sweep and scatter_rates together, and their loops
  !> are the team's orphaned worksharing loops (no region of their own). Per thread, so that
  !> the thread that runs a `single` section can clear it there (gather_sorted,
  !> list_rebuild.f90).
  logical, save :: open_team = .false.
  !$omp threadprivate(open_team)

  !> Particle loops for in_team: run(which) holds orphaned worksharing loops (!$omp do) and
  !> is called by every thread of a parallel region, or by this thread alone.
  type, abstract :: team_work_t
  contains
    procedure(team_run_i), deferred :: run
  end type team_work_t

  abstract interface
    subroutine team_run_i(self, which)
      import :: team_work_t
      class(team_work_t), intent(inout) :: self
      integer, intent(in) :: which
    end subroutine team_run_i
  end interface

contains

  !> Runs work%run(which) in a parallel region, or directly when one thread is in use
  !> (one_thread: no region, no barrier) or when every thread of an open team calls it
  !> (set_open_team).
  subroutine in_team(work, which)
    class(team_work_t), intent(inout) :: work
    integer, intent(in) :: which
    if (one_thread() .or. open_team) then
      call work%run(which)
    else
      !$omp parallel
      call work%run(which)
      !$omp end parallel
    end if
  end subroutine in_team

  !> Whether the next parallel regions would have one thread. Then the loops run without a
  !> region (their orphaned worksharing constructs serially): with libgomp every barrier, and
  !> so every region, costs a futex system call even for a team of one, and a small case's
  !> step has dozens of them. Not in a parallel region: a thread alone in a team's `single`
  !> section must open a (nested, one-thread) region for orphaned loops.
  logical function one_thread()
    one_thread = .true.
    !$ one_thread = omp_get_max_threads() == 1 .and. .not. omp_in_parallel()
  end function one_thread

  !> Whether this thread is one of an open team (set_open_team) whose threads all call the
  !> particle loops together.
  logical function in_open_team()
    in_open_team = open_team
  end function in_open_team

  !> Every thread of a parallel region calls this with .true. at its start (the loops called
  !> afterwards run as the region's orphaned worksharing loops) and with .false. at its end.
  subroutine set_open_team(on)
    logical, intent(in) :: on
    open_team = on
  end subroutine set_open_team

end module omp_team
