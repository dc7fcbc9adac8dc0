import sys; sys.path.insert(0,'/tmp/research22')
from proto import *
s=float(sys.argv[1]) if len(sys.argv)>1 else 10
bb=read_fits('/tmp/research22/bb_h.fits'); pn=read_fits('/tmp/research22/pine_h.fits')
R={}
for name,h in [('bb',bb),('pine',pn)]:
    for part,sub in [('full',h),('L',h[:,:512]),('R',h[:,512:]),('T',h[:512]),('B',h[512:])]:
        R[(name,part)]=stats(sub,s)[0]
    print(name, fmt(R[(name,'full')]))
    print('  hist', np.round(R[(name,'full')]['hist'],3))
sets={'7':CORE,
 'no_hstd':[k for k in CORE if k!='spacing_h_std'],
 'no_vf':[k for k in CORE if k!='vertical_fraction'],
 'no_ff':[k for k in CORE if k!='fissure_fraction'],
 'cv':['fissure_fraction','vertical_fraction','spacing_h_mean','spacing_h_std','width_mean','length_median','depth_ratio','width_std','spacing_v_mean']}
for nm,c in sets.items():
    out=[]
    for name in ('bb','pine'):
        out.append(score(R[(name,'L')],R[(name,'R')],c)[0]); out.append(score(R[(name,'T')],R[(name,'B')],c)[0])
    x=score(R[('bb','full')],R[('pine','full')],c)[0]
    print(nm, 'halves', np.round(out,3), 'bb-pine', round(x,3))
