; indp_beside_path: independent (INDP) axes beside the path on static_saw (docs/ipo.md "INDP
;   axes and technology functions"). Z lowers with INDP_SYN and TIME= (the path stops before
;   it, the next block waits until Z is in position); C turns with INDP_ASYN while X and Y
;   cut, #WAIT INDP [C] waits for it; C returns in G00 beside the path; M and H functions
;   are output with their time and line (`# tech` comments in the run CSV).
; static_saw; C between -3600 and 3600 degrees, X 0..200, Y 0..100, Z 0..50.
%indp_beside_path
N10 G17 G90 G71 G94
N20 G00 X0 Y0 Z50 C0
N30 Z[INDP_SYN G01 G90 POS=20 TIME=1.5]     ; 1.5 s, the next block waits for it
N40 C[INDP_ASYN G01 G90 POS=180 FEED=18000] ; 300 deg/s beside the path
N50 G01 X100 F6000 M50                      ; laser on (technology function)
N60 G01 Y50
N70 #WAIT INDP [C]
N80 C[INDP_ASYN G00 G90 POS=0]              ; back at the rapid velocity beside the path
N90 G01 X0 Y0 F12000 H7
N100 Z[INDP_SYN G00 G90 POS=50]
N110 M51                                    ; laser off
N120 M30
