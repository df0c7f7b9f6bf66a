#!/usr/bin/env bash
# Prints a DXF drawing in millimetres as CAD programs write it: a 20 m square of rock
# (LWPOLYLINE, layer "rock"), a 4 m opening (POLYLINE/VERTEX/SEQEND, layer "holes"), a joint
# (LINE), a fault (open LWPOLYLINE), a monitoring point (POINT) and a CIRCLE mcdda does not import.
g() { printf '%s\n%s\n' "$1" "$2"; }
g 0 SECTION; g 2 HEADER; g 9 '$INSUNITS'; g 70 4; g 0 ENDSEC
g 0 SECTION; g 2 ENTITIES
g 0 LWPOLYLINE; g 8 rock; g 90 4; g 70 1
for p in "0 0" "20000 0" "20000 20000" "0 20000"; do set -- $p; g 10 "$1"; g 20 "$2"; done
g 0 POLYLINE; g 8 holes; g 66 1; g 70 1
for p in "8000 8000" "8000 12000" "12000 12000" "12000 8000"; do set -- $p; g 0 VERTEX; g 8 holes; g 10 "$1"; g 20 "$2"; g 30 0; done
g 0 SEQEND
g 0 LINE; g 8 joints; g 10 0; g 20 15000; g 11 20000; g 21 16000
g 0 LWPOLYLINE; g 8 faults; g 90 3; g 70 0
for p in "0 4000" "6000 5000" "20000 3000"; do set -- $p; g 10 "$1"; g 20 "$2"; done
g 0 POINT; g 8 monitor; g 10 10000; g 20 18000
g 0 CIRCLE; g 8 0; g 10 3000; g 20 3000; g 40 500
g 0 ENDSEC; g 0 EOF
