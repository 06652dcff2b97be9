#!/bin/sh
# GRFLOW LIGGGHTS decks: LIGGGHTS's snapshot dumps in the formats of the
# LAMMPS decks (inputs/README.md, "Snapshots"), which analysis/ reads.
#
#   sh snapshot.sh atoms FILE
#       FILE: write_dump custom "id type radius x y z vx vy vz v_glue";
#       names the last column "glue", as LAMMPS's "modify colname" does
#       (LIGGGHTS's dumps have no colname).  In place.
#
#   sh snapshot.sh contacts IN OUT LX LY
#       IN: write_dump local of compute pair/gran/local "pos id force"
#       (xi yi zi xj yj zj id_i id_j periodic fx fy fz: positions mapped
#       into the box, the force on i); OUT: the contacts file of the LAMMPS
#       decks, "ITEM: ENTRIES id1 id2 dx dy dz fn ftx fty ftz": the branch
#       vector x_i - x_j (the nearest periodic image in x and y, with the
#       box lengths LX LY given in full: the dump's box bounds have 6
#       digits; the cell is at least 2 d_max wide, prepare.liggghts), the
#       normal force
#       fn = F.n with n = (x_i - x_j)/|x_i - x_j| (compression positive),
#       and the tangential force F - fn n on id1.  IN is removed.
set -e
case "$1" in
  atoms)
    [ $# -eq 2 ] || { echo "usage: sh snapshot.sh atoms FILE" >&2; exit 1; }
    tmp=$(mktemp "$2.XXXXXX")
    sed '/^ITEM: ATOMS /s/ v_glue *$/ glue/' "$2" > "$tmp"
    mv -f "$tmp" "$2"
    ;;
  contacts)
    [ $# -eq 5 ] || { echo "usage: sh snapshot.sh contacts IN OUT LX LY" >&2; exit 1; }
    tmp=$(mktemp "$3.XXXXXX")
    awk -v lx="$4" -v ly="$5" '
      function nearest(d, L) { return d - L * int(d / L + (d >= 0 ? 0.5 : -0.5)) }
      /^ITEM: ENTRIES/ { print "ITEM: ENTRIES id1 id2 dx dy dz fn ftx fty ftz"; data = 1; next }
      /^ITEM:/ { print; data = 0; next }
      !data { print; next }
      {
        dx = nearest($1 - $4, lx)
        dy = nearest($2 - $5, ly)
        dz = $3 - $6
        r = sqrt(dx * dx + dy * dy + dz * dz)
        nx = dx / r; ny = dy / r; nz = dz / r
        fn = $10 * nx + $11 * ny + $12 * nz
        printf "%d %d %.10g %.10g %.10g %.10g %.10g %.10g %.10g\n", $7, $8, dx, dy, dz, fn,
               $10 - fn * nx, $11 - fn * ny, $12 - fn * nz
      }' "$2" > "$tmp"
    mv -f "$tmp" "$3"
    rm -f "$2"
    ;;
  *)
    echo "usage: sh snapshot.sh atoms FILE | contacts IN OUT LX LY" >&2; exit 1 ;;
esac
