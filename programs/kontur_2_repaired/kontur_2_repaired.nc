; kontur_2_repaired: programs/kontur_2 with X parked at 5 m/min after #SYNC OUT, as the
;   listing meant: as printed, FEED5 (mm/min) parks X from about X50 in PCS1 carried by the
;   belt in 582.5 s of the run's 587.65 s.
; kontur_2: machining a single workpiece with #SYNC IN/OUT.
; source: TF5264 Conveyor Tracking (seed 004), section 3 "Programming",
;   listing "Machining a single workpiece with #SINC IN/OUT".
; repaired: the whole listing was extracted as one line; blocks split back into one block
;   per line at each N word (PDF extraction)
%kontur_2_repaired
N0010 G0 X0 Y0 Z200
N0020 T1 D1 ;Select tool
N0030 G00 G90 X0 Y0 Z50
; repaired: "MC TouchProbe" -> "MC_TouchProbe" (PDF extraction)
N0040 S1 [MC_TouchProbe Channel=1] ;Read measured value
N0050 #SYNC IN [CONV_VEL 30] ;Select synchronisation
N0060 G0 X50 Y0 ;Position on moving workpiece
N0070 #CS ON[0,0,0,0,0,45]
N0080 G01 X50 F5000
N0090 G01 Y50
N0100 G01 X-50
N0110 G01 Y-50
N0120 #CS OFF
; repaired: "FEED CONT" -> "FEED_CONT" (PDF extraction)
N0130 #SYNC OUT [FEED_CONT=5] ;Select desynchronisation
; repaired: "FEED5" -> "FEED5000": FEED is in mm/min; 5 mm/min parks X in almost ten
;   minutes, so the listing's 5 is read as m/min (as in programs/sync_wait_repaired)
N0140 X[INDP_SYN G1 POS0 FEED5000 INTERRUPTIBLE] ; Position in MCS
N0150 G00 X0 Y0 Z50
N0160 M30
