import sys; sys.path.insert(0,'/tmp/research22')
from emdtest import ang_w, hist_c
from synth import stripes
import numpy as np
for ang in (90,75,60,45,30,15,0):
    a,w=ang_w(stripes(32,5,ang))
    m=np.degrees(0.5*np.angle((w*np.exp(2j*np.radians(a))).sum()))%180
    h=hist_c(a,w,10); print(ang, 'mean', round(m,2), 'peak bin', int(np.argmax(h))*10, 'mass', round(h.max(),3))
