!> Cubic B-spline kernel in 2D (Monaghan & Lattanzio 1985), support 2h:
!> W = 10/(7 pi h^2) (1 - 1.5 q^2 + 0.75 q^3) for q < 1, 10/(7 pi h^2) (2 - q)^3 / 4 for 1 <= q < 2.
!> Its gradient with Thomas & Couchman's (1992) change (cubic_tc_dfdq): df/dq held at its
!> q = 2/3 value, -1, inside q = 2/3, where the spline's own falls to 0 at q = 0. A pair closer
!> than 2/3 h then repels as hard as one at 2/3 h, which is what keeps rows from pairing. Below
!> TC_CORE df/dq goes linearly to 0: F = (dW/dr)/r stays finite (-1/TC_CORE norm/h^4) where a
!> constant df/dq gives F ~ 1/r, whose integral over a ring's azimuth (the rings pair's tables,
!> physics/axisymmetric.f90) is unbounded as two rings meet near the axis. TC_CORE = 0.25 lies
!> below the nearest lattice neighbour (q = dx/h) at every h below 4 dx.
module kernel_cubic
  use sphjet_kinds, only: rp, pi
  implicit none
  private
  public :: cubic_norm, cubic_f, cubic_dfdq, cubic_tc_dfdq

  real(rp), parameter :: cubic_norm = 10.0_rp / (7.0_rp * pi)
  real(rp), parameter :: TC_CORE = 0.25_rp

contains

  pure elemental function cubic_f(q) result(f)
    real(rp), intent(in) :: q
    real(rp) :: f
    if (q < 1.0_rp) then
      f = 1.0_rp - 1.5_rp * q * q + 0.75_rp * q**3
    else if (q < 2.0_rp) then
      f = 0.25_rp * (2.0_rp - q)**3
    else
      f = 0.0_rp
    end if
  end function cubic_f

  pure elemental function cubic_dfdq(q) result(df)
    real(rp), intent(in) :: q
    real(rp) :: df
    if (q < 1.0_rp) then
      df = -3.0_rp * q + 2.25_rp * q * q
    else if (q < 2.0_rp) then
      df = -0.75_rp * (2.0_rp - q)**2
    else
      df = 0.0_rp
    end if
  end function cubic_dfdq

  !> df/dq with Thomas & Couchman's gradient (the module's comment).
  pure elemental function cubic_tc_dfdq(q) result(df)
    real(rp), intent(in) :: q
    real(rp) :: df
    if (q < TC_CORE) then
      df = -q / TC_CORE
    else if (q < 2.0_rp / 3.0_rp) then
      df = -1.0_rp
    else
      df = cubic_dfdq(q)
    end if
  end function cubic_tc_dfdq

end module kernel_cubic
