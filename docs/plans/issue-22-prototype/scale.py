import sys; sys.path.insert(0,'/tmp/research22')
from proto import *
from scipy import ndimage as ndi
def down(h, f):  # anti-aliased downsample by factor f
    return ndi.zoom(ndi.gaussian_filter(h, 0.5*f), 1.0/f, order=3)
bb=read_fits('/tmp/research22/bb_h.fits'); pn=read_fits('/tmp/research22/pine_h.fits')
for name,h in [('bb',bb),('pine',pn)]:
    a=stats(h,10)[0]
    b=stats(down(h,2),5)[0]        # same physical scale, declared correctly
    c=stats(down(h,2),10)[0]       # 2x scale mismatch
    print(name,'same field two scales, declared', round(score(a,b)[0],3), ' mismatch 2x', round(score(a,c)[0],3))
    # halves at 5 px/cm
    L=stats(down(h[:,:512],2),5)[0]; R=stats(down(h[:,512:],2),5)[0]
    T=stats(down(h[:512],2),5)[0]; B=stats(down(h[512:],2),5)[0]
    print(name,'halves at 5 px/cm', round(score(L,R)[0],3), round(score(T,B)[0],3))
a=stats(down(bb,2),5.12)[0]; b=stats(down(pn,2),5.12)[0]; print('bb-pine at 5.12', round(score(a,b)[0],3), 'emd', round(emd_circ(a['hist'],b['hist']),2))
