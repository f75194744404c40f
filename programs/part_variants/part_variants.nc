; part_variants: ncsim's own program for a scenario: the PLC side tells the program which part
;   to cut (V.E.PART_TYPE: 1 a square, 2 a circle) and where (V.E.X_OFFSET, mm), as a line
;   PLC does through V.E. variables. The values come from this folder's scenario.toml (used by
;   default; docs/scenario.md); `--ve NAME=value` overrides one of them for check and trace.
; Every move stays inside X 0..80, Y 0..45, Z -2.5..10 (portal_3x) for X_OFFSET 0..40.
%part_variants
N10 G17 G90 G71 G94
N20 G00 X[V.E.X_OFFSET] Y10 Z5
N30 G01 Z-1 F600
$IF V.E.PART_TYPE == 1
N40 G91 X20
N50 Y20
N60 X-20
N70 Y-20
N80 G90
$ELSEIF V.E.PART_TYPE == 2
N90 G02 X[V.E.X_OFFSET + 20] Y10 I10 J0
N100 G02 X[V.E.X_OFFSET] Y10 I-10 J0
$ELSE
N110 #MSG ["unknown V.E.PART_TYPE"]
$ENDIF
N120 G00 Z5
N130 M30
