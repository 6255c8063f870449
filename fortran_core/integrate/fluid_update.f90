!> The per-particle updates both integrators share (predictor_corrector.f90, leapfrog.f90):
!> which particles they advance, and the pressure and sound speed of a particle from its
!> density (the Tait EoS, physics/eos_tait.f90).
module fluid_update
  use sphjet_kinds, only: rp, ip, KIND_FLUID
  use sphjet_types, only: sph_params_t, state_t
  use eos_tait, only: tait_pressure, tait_sound_speed
  implicit none
  private
  public :: update_eos, eos_one, moving_fluid, moves

contains

  !> p and c from rho for particles first..last.
  subroutine update_eos(prm, st, first, last)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer, intent(in) :: first, last
    integer :: i
    !$omp parallel do schedule(static)
    do i = first, last
      call eos_one(prm, st, i)
    end do
    !$omp end parallel do
  end subroutine update_eos

  !> p and c of particle i from its density.
  subroutine eos_one(prm, st, i)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer, intent(in) :: i
    st%p(i) = tait_pressure(st%rho(i), prm%eos%rho0, prm%eos%b, prm%eos%gamma)
    st%c(i) = tait_sound_speed(st%rho(i), prm%eos%rho0, prm%eos%c0)
  end subroutine eos_one

  !> Whether particle i is fluid still in the domain (the particles the integrator advances).
  pure logical function moving_fluid(st, i)
    type(state_t), intent(in) :: st
    integer, intent(in) :: i
    moving_fluid = moves(st%active(i), st%kind(i))
  end function moving_fluid

  !> The same from a particle's active flag and kind.
  pure elemental logical function moves(active, kind)
    integer(ip), intent(in) :: active, kind
    moves = active /= 0 .and. kind == KIND_FLUID
  end function moves

end module fluid_update
