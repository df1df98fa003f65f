# The HP 5451C keyboard program of Basmaji (1983), App. E: ten power spectra of the
# analogue input summed into block 1, divided by ten, shown linear and then in dB.
LABEL 0
CLEAR BLOCK 1
LABEL 1
ANALOG IN CHANNEL 0 BLOCK 1
FOURIER TRANSFORM
POWER SPECTRUM
COUNT LOOP LABEL 1 TIMES 10
DIVIDE BLOCK 1 BY 10
DISPLAY
LOG
DISPLAY
END
