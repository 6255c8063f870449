!> Per-particle checks after a step: particles leaving the domain (removed and counted, as
!> SPHysics does, or reported), a blow-up (NaN/Inf, density outside the sane band), and the
!> rings too heavy for their radius (domain.split_axis_rings).
module state_checks
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use sphjet_kinds, only: rp, ip, i8, KIND_FLUID, SPH_OK, SPH_ERR_NONFINITE, SPH_ERR_DENSITY, &
                          SPH_ERR_OUT_OF_DOMAIN, GEOM_AXISYMMETRIC
  use sphjet_types, only: sph_params_t, state_t
  use axisymmetric, only: ring_too_heavy
  implicit none
  private
  public :: check_domain, check_finite, fold_into_domain, reflect_at_axis, rings_to_split

contains

  !> The active fluid rings too heavy for their radius (physics/axisymmetric.f90,
  !> ring_too_heavy): their 0-based indices in idx (the first capacity of them) and their number.
  subroutine rings_to_split(prm, st, capacity, idx, n_found)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(in) :: st
    integer(i8), intent(in) :: capacity
    integer(i8), intent(inout) :: idx(*)
    integer(i8), intent(out) :: n_found
    integer :: i
    n_found = 0
    do i = st%nb + 1, st%n
      if (st%active(i) == 0 .or. st%kind(i) /= KIND_FLUID) cycle
      if (.not. ring_too_heavy(st%m(i), st%x(i), prm%geometry%ring_mass_per_radius, prm%geometry%axis_m1)) cycle
      n_found = n_found + 1
      if (n_found <= capacity) idx(n_found) = i - 1
    end do
  end subroutine rings_to_split

  !> Fluid particles beyond [domain%xmin, xmax] x [domain%zmin, zmax] leave the domain.
  !> With domain%remove_out they become inactive (velocity zeroed) and are counted;
  !> otherwise the first one is reported (status SPH_ERR_OUT_OF_DOMAIN, bad = its index).
  subroutine check_domain(prm, st, n_removed, bad, status)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer(i8), intent(out) :: n_removed
    integer(i8), intent(out) :: bad
    integer(ip), intent(out) :: status
    integer :: i
    n_removed = 0
    bad = -1
    status = SPH_OK
    do i = st%nb + 1, st%n
      if (st%active(i) == 0 .or. st%kind(i) /= KIND_FLUID) cycle
      if (st%x(i) > prm%domain%xmax .or. st%x(i) < prm%domain%xmin .or. &
          st%z(i) < prm%domain%zmin .or. st%z(i) > prm%domain%zmax) then
        if (prm%domain%remove_out /= 0) then
          st%active(i) = 0
          st%u(i) = 0.0_rp
          st%w(i) = 0.0_rp
          n_removed = n_removed + 1
        else
          bad = i - 1
          status = SPH_ERR_OUT_OF_DOMAIN
          return
        end if
      end if
    end do
  end subroutine check_domain

  !> Axisymmetric mode, within a step, after its particles have moved and before the rates are
  !> evaluated there: a fluid particle that has crossed the axis (x < 0) is reflected with what
  !> the rest of the step uses of it, x, u and the start-of-step xo and uo (x -> -x and the
  !> rest negated: it is now where its mirror image was, moving as that one; the evaluation
  !> then sets its XSPH velocity anew). Evaluated at x < 0, the rings pair (domain.axis_pair =
  !> "rings") took the ring for an axis image and gave it no pairs: its density rate only the
  !> term of its own far side, no pressure force. In a drop the rings that cross the axis
  !> gathered there, 2.5 times as dense as their densities said, until one ran out of the
  !> density check's band (cases/round_jet/README.md). One thread (in an open team,
  !> omp_team.f90: the one of a `single`, the others wait at its end).
  subroutine reflect_at_axis(prm, st)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer :: i
    if (prm%geometry%kind /= GEOM_AXISYMMETRIC) return
    !$omp single
    do i = st%nb + 1, st%n
      if (st%active(i) == 0 .or. st%kind(i) /= KIND_FLUID) cycle
      if (st%x(i) < 0.0_rp) then
        st%x(i) = -st%x(i)
        st%u(i) = -st%u(i)
        st%xo(i) = -st%xo(i)
        st%uo(i) = -st%uo(i)
      end if
    end do
    !$omp end single
  end subroutine reflect_at_axis

  !> After a step, before check_domain: with a periodic z a fluid particle beyond domain%zmax
  !> (below zmin) re-enters at the other end, z -+ lz. The axis is reflect_at_axis's, which each
  !> integrator calls where a move can carry a ring across it.
  subroutine fold_into_domain(prm, st)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(inout) :: st
    integer :: i
    real(rp) :: lz
    if (prm%geometry%periodic_z == 0) return
    lz = prm%domain%zmax - prm%domain%zmin
    !$omp parallel do schedule(static)
    do i = st%nb + 1, st%n
      if (st%active(i) == 0 .or. st%kind(i) /= KIND_FLUID) cycle
      if (st%z(i) >= prm%domain%zmax) then
        st%z(i) = st%z(i) - lz
      else if (st%z(i) < prm%domain%zmin) then
        st%z(i) = st%z(i) + lz
      end if
    end do
    !$omp end parallel do
  end subroutine fold_into_domain

  !> First active particle with a non-finite field or a density outside [rho_min, rho_max].
  subroutine check_finite(prm, st, bad, status)
    type(sph_params_t), intent(in) :: prm
    type(state_t), intent(in) :: st
    integer(i8), intent(out) :: bad
    integer(ip), intent(out) :: status
    integer :: i
    bad = -1
    status = SPH_OK
    do i = 1, st%n
      if (st%active(i) == 0) cycle
      if (.not. (ieee_is_finite(st%x(i)) .and. ieee_is_finite(st%z(i)) .and. &
                 ieee_is_finite(st%u(i)) .and. ieee_is_finite(st%w(i)) .and. &
                 ieee_is_finite(st%rho(i)) .and. ieee_is_finite(st%p(i)))) then
        bad = i - 1
        status = SPH_ERR_NONFINITE
        return
      end if
      if (prm%domain%rho_max > 0.0_rp .and. &
          (st%rho(i) < prm%domain%rho_min .or. st%rho(i) > prm%domain%rho_max)) then
        bad = i - 1
        status = SPH_ERR_DENSITY
        return
      end if
    end do
  end subroutine check_finite

end module state_checks
