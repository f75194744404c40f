; touch_probe_mode: the MC_TouchProbe example line with an explicit trigger mode (rising edge).
; source: TF5264 Conveyor Tracking (seed 004), section 3.1 "MC_TouchProbe command", example
;   line under the PLCopen block diagram. The manual gives this single block; the program
;   header and end are added to make it a program.
; added: program header
%touch_probe_mode
S[MC_TouchProbe Channel=1 Mode=2]
; added: program end M30
M30
