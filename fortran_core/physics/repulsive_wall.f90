!> Repulsive wall force of Monaghan & Kos (1999) with the corrections of Rogers et al. (2008),
!> as SPHysics 2D v2.2 applies it (SPHysics guide eqs 2.12-2.16): a fluid particle closer than
!> 2h to a wall particle along the wall normal is pushed along that normal by
!>   f = n P(xi) R(psi) eps(z, u_n),
!>   R = A (1 - q)/sqrt(q), q = psi / 2h,
!>   A = 0.01 c^2 / beta^2 / h  (minus c u_n / beta / h when the particle moves away, u_n > 0),
!>   P = (1 + cos(pi xi / delta)) / 2 with xi the tangential offset and delta the spacing to the
!>       wall neighbour on that side (the force stays constant while sliding along the wall),
!>   eps = eps_z + eps_dyn: depth correction (1 near the bottom, 0.02 + |1 - z/h_SWL| + dynamic
!>       head below still water, 0.02 + dynamic head above) and eps_dyn = min(40 |u_n|/c0, 1)
!>       for approaching particles. The dynamic head is that of the wall's normal velocity
!>       (legacy: its whole velocity; the same for walls at rest, see below).
!> beta = coef/10 scales the force with the speed-of-sound coefficient of the case.
module repulsive_wall
  use sphjet_kinds, only: rp, pi
  implicit none
  private
  public :: repulsive_force, wall_normal

contains

  !> Acceleration (fx, fz) of a fluid particle from one wall particle.
  pure subroutine repulsive_force(drx, drz, dux, duz, nx, nz, dback, dfwd, c_fluid, c0, &
                                  z_fluid, z_wall, u_wall, w_wall, h, h_swl, g, beta, fx, fz)
    real(rp), intent(in) :: drx, drz       !< r_fluid - r_wall
    real(rp), intent(in) :: dux, duz       !< u_fluid - u_wall
    real(rp), intent(in) :: nx, nz         !< wall unit normal (into the fluid)
    real(rp), intent(in) :: dback, dfwd    !< spacing to the previous / next wall particle
    real(rp), intent(in) :: c_fluid, c0, z_fluid, z_wall, u_wall, w_wall, h, h_swl, g, beta
    real(rp), intent(out) :: fx, fz
    real(rp), parameter :: eps_min = 0.02_rp
    real(rp) :: psi, xi, delta, q, un, a, eps_z, eps_dyn, dyn_head, f

    fx = 0.0_rp
    fz = 0.0_rp
    psi = drx * nx + drz * nz
    if (psi <= 0.0_rp) return
    q = psi / (2.0_rp * h)
    if (q >= 1.0_rp) return
    ! tangent t = (nz, -nx); xi = projection of r_fluid - r_wall on it
    xi = (drx - psi * nx) * nz - (drz - psi * nz) * nx
    delta = merge(dfwd, dback, xi > 0.0_rp)
    if (abs(xi) >= delta) return

    un = dux * nx + duz * nz
    if (un > 0.0_rp) then
      a = (0.01_rp * c_fluid * c_fluid / (beta * beta) - c_fluid * un / beta) / h
    else
      a = 0.01_rp * c_fluid * c_fluid / (beta * beta) / h
    end if

    eps_z = abs(1.0_rp - z_wall / h_swl)
    ! Dynamic head of the wall's motion along its normal (a wall pushing into the water). Legacy
    ! squares the whole wall velocity; the only moving walls here are gates, which slide along
    ! themselves, and that velocity would scale the push by 1 + v^2 / (2 g h_SWL) (x5 for a
    ! 3 m/s gate in a 0.11 m column) and throw the water through a fast gate. Walls at rest: same.
    ! The dynamic head of a moving wall; without gravity it has no scale and is left out
    ! (0/0 for a wall at rest otherwise).
    dyn_head = 0.0_rp
    if (g /= 0.0_rp) dyn_head = (u_wall * nx + w_wall * nz)**2 / (2.0_rp * abs(g) * h_swl)
    if (eps_z > 1.0_rp - eps_min) then
      eps_z = 1.0_rp
    else if (z_fluid > h_swl) then
      eps_z = eps_min + dyn_head
    else
      eps_z = eps_min + eps_z + dyn_head
    end if
    if (un > 0.0_rp) then
      eps_dyn = 0.0_rp
    else
      eps_dyn = min(40.0_rp * abs(un) / c0, 1.0_rp)
    end if

    f = 0.5_rp * (1.0_rp + cos(pi * abs(xi) / delta)) * a * (eps_z + eps_dyn) &
        * (1.0_rp - q) / sqrt(q)
    fx = nx * f
    fz = nz * f
  end subroutine repulsive_force

  !> Normal of a wall particle from its neighbours along the wall (a wall end names itself as
  !> its missing neighbour and is extended by reflection), and the spacing on either side.
  pure subroutine wall_normal(xp, zp, x, z, xn, zn, is_first, is_last, h, nx, nz, dback, dfwd)
    real(rp), intent(in) :: xp, zp, x, z, xn, zn  !< previous, this, next particle
    logical, intent(in) :: is_first, is_last
    real(rp), intent(in) :: h
    real(rp), intent(out) :: nx, nz, dback, dfwd
    real(rp) :: xprev, zprev, xnext, znext, tx, tz, len
    xprev = xp; zprev = zp; xnext = xn; znext = zn
    if (is_first) then
      xprev = 2.0_rp * x - xn
      zprev = 2.0_rp * z - zn
    else if (is_last) then
      xnext = 2.0_rp * x - xp
      znext = 2.0_rp * z - zp
    end if
    tx = xnext - xprev
    tz = znext - zprev
    len = sqrt(tx * tx + tz * tz)
    if (len > 0.0_rp) then
      nx = -tz / len
      nz = tx / len
    else  ! neighbours on top of each other (not expected: a repulsive gate stops before its
          ! particles meet): no normal, no push
      nx = 0.0_rp
      nz = 0.0_rp
    end if
    dback = sqrt((x - xprev)**2 + (z - zprev)**2)
    dfwd = sqrt((xnext - x)**2 + (znext - z)**2)
    if (dback <= 0.0_rp) dback = 1.0e-3_rp * h
    if (dfwd <= 0.0_rp) dfwd = 1.0e-3_rp * h
  end subroutine wall_normal

end module repulsive_wall
