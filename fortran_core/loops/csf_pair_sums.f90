!> The CSF passes' sums over one pair list (surface_tension_loops.f90 calls them per row task
!> of the common traversal): colour, normal and free-surface delta, curvature, the surface
!> fit's least-squares sums, and the rings pair's mean curvature. Each is pure, takes the list's
!> arrays (pairs a < b within 2h, skipping the pairs with a boundary particle, pl%mixed) and the
!> per-slot fields, and adds each pair's terms to both slots in list order, so that the sums do
!> not depend on the thread count. The per-pair formulas are in physics/surface_tension.f90.
module csf_pair_sums
  use sphjet_kinds, only: rp
  use surface_tension, only: csf_normal_pair, csf_curvature_pair, csf_tangential_pair, csf_fit_point, &
                             N_FIT
  implicit none
  private
  public :: colour_pairs, normal_pairs, curvature_pairs, surface_fit_pairs, band_curvature_pairs, &
            surface_mean_pairs, NG_NX, NG_NZ, NG_GX, NG_GZ, N_NG

  !> Rows of surface_tension_loops' csf_work_t%ng, a slot's normal sums: the normal n (eq 18)
  !> x, z and the free-surface delta's sum_b V_b (g_a + g_b) grad_a W_ab x, z
  integer, parameter :: NG_NX = 1, NG_NZ = 2, NG_GX = 3, NG_GZ = 4, N_NG = 4

contains

  !> The sums of the weighted mean curvature of the fluid pairs of a list (the rings pair):
  !> num += w_b kappa_b V_b W_ab, den += w_b V_b W_ab, and b's likewise.
  pure subroutine surface_mean_pairs(np, pa, pb, w, mixed, v, wx, kx, num, den)
    integer, intent(in) :: np, pa(*), pb(*)
    real(rp), intent(in) :: w(*), v(*), wx(*), kx(*)
    logical, intent(in) :: mixed(*)
    real(rp), intent(inout) :: num(*), den(*)
    integer :: k, a, b
    do k = 1, np
      if (mixed(k)) cycle
      a = pa(k)
      b = pb(k)
      num(a) = num(a) + wx(b) * kx(b) * v(b) * w(k)
      den(a) = den(a) + wx(b) * v(b) * w(k)
      num(b) = num(b) + wx(a) * kx(a) * v(a) * w(k)
      den(b) = den(b) + wx(a) * v(a) * w(k)
    end do
  end subroutine surface_mean_pairs

  !> Colour sums (eq 14) of the fluid pairs of a list; two (axisymmetric): also the second
  !> colour c2 with the weights v2, in the same loop (otherwise v2, c2 are not referenced).
  !> A particle's pairs follow each other in the list (neighbours/verlet_list.f90) and none
  !> of them has it as b: its sums are carried along its run (the same additions in the
  !> same order as one pair at a time), as in rates.f90.
  pure subroutine colour_pairs(two, np, pa, pb, w, mixed, v, v2, c, c2)
    logical, intent(in) :: two
    integer, intent(in) :: np, pa(*), pb(*)
    real(rp), intent(in) :: w(*), v(*), v2(*)
    logical, intent(in) :: mixed(*)
    real(rp), intent(inout) :: c(*), c2(*)
    integer :: k, a, b
    real(rp) :: ca, c2a
    k = 1
    do while (k <= np)
      a = pa(k)
      ca = c(a)
      if (two) c2a = c2(a)
      do while (k <= np)
        if (pa(k) /= a) exit
        if (.not. mixed(k)) then
          b = pb(k)
          ca = ca + v(b) * w(k)
          c(b) = c(b) + v(a) * w(k)
          if (two) then
            c2a = c2a + v2(b) * w(k)
            c2(b) = c2(b) + v2(a) * w(k)
          end if
        end if
        k = k + 1
      end do
      c(a) = ca
      if (two) c2(a) = c2a
    end do
  end subroutine colour_pairs

  !> Normal (eq 18) and the free-surface delta's pair sums sum_b V_b (g_a + g_b) grad_a W_ab
  !> of the fluid pairs of a list, in one loop (independent sets of sums): for the delta,
  !> planar V = m/rho, g = 1/2 (sum_b V_b grad_a W_ab, doubled by the caller: g_a + g_b = 1,
  !> so the pair's gradient is the normal's); axisymmetric V = m/(2 pi rho) and g = 1/g(x)
  !> (the weights of its pressure pair). two (axisymmetric): also the gradient n2 of the
  !> second colour c2 with the weights vmu, in the same loop; otherwise gi, c2, n2x, n2z are
  !> not referenced. The normal and delta sums go to ng(NG_*, slot) (csf_work_t%ng).
  pure subroutine normal_pairs(two, np, pa, pb, dx, dz, f, mixed, v, c, vmu, gi, c2, ng, &
                               n2x, n2z)
    logical, intent(in) :: two
    integer, intent(in) :: np, pa(*), pb(*)
    real(rp), intent(in) :: dx(*), dz(*), f(*), v(*), c(*), vmu(*), gi(*), c2(*)
    logical, intent(in) :: mixed(*)
    real(rp), intent(inout) :: ng(N_NG, *), n2x(*), n2z(*)
    integer :: k, a, b
    real(rp) :: gx, gz, da1, da2, db1, db2, gsum, s2x, s2z
    real(rp) :: sa(N_NG)
    k = 1
    do while (k <= np)   ! a's sums carried along its run (colour_pairs)
      a = pa(k)
      sa = ng(:, a)
      if (two) then
        s2x = n2x(a)
        s2z = n2z(a)
      end if
      do while (k <= np)
        if (pa(k) /= a) exit
        if (.not. mixed(k)) then
          b = pb(k)
          gx = f(k) * dx(k)
          gz = f(k) * dz(k)
          call csf_normal_pair(v(a), v(b), c(a), c(b), gx, gz, da1, da2, db1, db2)
          sa(NG_NX) = sa(NG_NX) + da1
          sa(NG_NZ) = sa(NG_NZ) + da2
          ng(NG_NX, b) = ng(NG_NX, b) + db1
          ng(NG_NZ, b) = ng(NG_NZ, b) + db2
          if (two) then
            call csf_normal_pair(vmu(a), vmu(b), c2(a), c2(b), gx, gz, da1, da2, db1, db2)
            s2x = s2x + da1
            s2z = s2z + da2
            n2x(b) = n2x(b) + db1
            n2z(b) = n2z(b) + db2
            gsum = (gi(a) + gi(b)) * f(k)
            gx = gsum * dx(k)
            gz = gsum * dz(k)
          end if   ! planar: g_a + g_b = 1/2 + 1/2 = 1 exactly, and gx, gz are the normal's
          sa(NG_GX) = sa(NG_GX) + vmu(b) * gx
          sa(NG_GZ) = sa(NG_GZ) + vmu(b) * gz
          ng(NG_GX, b) = ng(NG_GX, b) - vmu(a) * gx
          ng(NG_GZ, b) = ng(NG_GZ, b) - vmu(a) * gz
        end if
        k = k + 1
      end do
      ng(:, a) = sa
      if (two) then
        n2x(a) = s2x
        n2z(a) = s2z
      end if
    end do
  end subroutine normal_pairs

  !> Curvature sums of the fluid pairs of a list whose particles both pass the filter: eq
  !> 23's numerator (num) and, into den, its Shepard denominator when shepard, else the
  !> tangential denominator of the free-surface curvature (csf_tangential_pair). Plain arrays,
  !> so that the loop keeps their addresses in registers.
  pure subroutine curvature_pairs(shepard, np, pa, pb, dx, dz, f, w, mixed, flag, v, nhx, nhz, &
                                  num, den)
    logical, intent(in) :: shepard
    integer, intent(in) :: np, pa(*), pb(*)
    real(rp), intent(in) :: dx(*), dz(*), f(*), w(*), flag(*), v(*), nhx(*), nhz(*)
    logical, intent(in) :: mixed(*)
    real(rp), intent(inout) :: num(*), den(*)
    integer :: k, a, b
    real(rp) :: da1, da2, db1, db2, sn, sd
    k = 1
    do while (k <= np)   ! a's sums carried along its run (colour_pairs)
      a = pa(k)
      if (flag(a) == 0.0_rp) then   ! none of a's pairs adds anything
        do while (k <= np)
          if (pa(k) /= a) exit
          k = k + 1
        end do
        cycle
      end if
      sn = num(a)
      sd = den(a)
      do while (k <= np)
        if (pa(k) /= a) exit
        b = pb(k)
        if (.not. mixed(k) .and. flag(b) /= 0.0_rp) then
          call csf_curvature_pair(flag(a), flag(b), v(a), v(b), nhx(a), nhz(a), nhx(b), &
                                  nhz(b), f(k) * dx(k), f(k) * dz(k), w(k), da1, da2, db1, db2)
          sn = sn + da1
          num(b) = num(b) + db1
          if (.not. shepard) call csf_tangential_pair(flag(a), flag(b), v(a), v(b), nhx(a), &
                                                      nhz(a), nhx(b), nhz(b), dx(k), dz(k), &
                                                      f(k), da2, db2)
          sd = sd + da2
          den(b) = den(b) + db2
        end if
        k = k + 1
      end do
      num(a) = sn
      den(a) = sd
    end do
  end subroutine curvature_pairs

  !> The surface fit (surface_tension.curvature = "surface_fit"): a flagged particle's sums take
  !> each outer neighbour's position relative to it, in its frame (csf_fit_point), weighted
  !> V_b W_ab.
  pure subroutine surface_fit_pairs(np, pa, pb, dx, dz, w, mixed, flag, outer, v, nhx, nhz, fit)
    integer, intent(in) :: np, pa(*), pb(*)
    real(rp), intent(in) :: dx(*), dz(*), w(*), flag(*), outer(*), v(*), nhx(*), nhz(*)
    logical, intent(in) :: mixed(*)
    real(rp), intent(inout) :: fit(N_FIT, *)
    integer :: k, a, b
    do k = 1, np
      if (mixed(k)) cycle
      a = pa(k)
      b = pb(k)
      ! dx = x_a - x_b: b lies at -dx from a, a at +dx from b
      if (flag(a) > 0.0_rp .and. outer(b) > 0.0_rp) &
        call csf_fit_point(v(b) * w(k), -dx(k), -dz(k), nhx(a), nhz(a), fit(:, a))
      if (flag(b) > 0.0_rp .and. outer(a) > 0.0_rp) &
        call csf_fit_point(v(a) * w(k), dx(k), dz(k), nhx(b), nhz(b), fit(:, b))
    end do
  end subroutine surface_fit_pairs

  !> The free-surface curvature's sums of the fluid pairs of a list with curvature_normals =
  !> "surface_band": as curvature_pairs (tangential denominator), but particle a (flag 1) takes
  !> neighbour b's normal only where b lies in the surface band (band 1), and b a's likewise.
  pure subroutine band_curvature_pairs(np, pa, pb, dx, dz, f, mixed, flag, band, v, nhx, nhz, &
                                       num, den)
    integer, intent(in) :: np, pa(*), pb(*)
    real(rp), intent(in) :: dx(*), dz(*), f(*), flag(*), band(*), v(*), nhx(*), nhz(*)
    logical, intent(in) :: mixed(*)
    real(rp), intent(inout) :: num(*), den(*)
    integer :: k, a, b
    real(rp) :: da1, da2, db1, db2, wa, wb
    do k = 1, np
      if (mixed(k)) cycle
      a = pa(k)
      b = pb(k)
      wa = flag(a) * band(b)
      wb = flag(b) * band(a)
      if (wa == 0.0_rp .and. wb == 0.0_rp) cycle
      call csf_curvature_pair(1.0_rp, 1.0_rp, v(a), v(b), nhx(a), nhz(a), nhx(b), nhz(b), &
                              f(k) * dx(k), f(k) * dz(k), 0.0_rp, da1, da2, db1, db2)
      num(a) = num(a) + wa * da1
      num(b) = num(b) + wb * db1
      call csf_tangential_pair(1.0_rp, 1.0_rp, v(a), v(b), nhx(a), nhz(a), nhx(b), nhz(b), &
                               dx(k), dz(k), f(k), da2, db2)
      den(a) = den(a) + wa * da2
      den(b) = den(b) + wb * db2
    end do
  end subroutine band_curvature_pairs

end module csf_pair_sums
