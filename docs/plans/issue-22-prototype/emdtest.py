import sys; sys.path.insert(0,'/tmp/research22')
import proto
from proto import *
bb=read_fits('/tmp/research22/bb_h.fits'); pn=read_fits('/tmp/research22/pine_h.fits')
def angles(h,s=10):
    o,m,sk=stats(h,s)
    return o, m, sk
# recompute angles directly to build centred histograms
def ang_w(h,s=10,p=P):
    h=(h-h.mean())/h.std()
    hp=h-ndi.gaussian_filter(h,p['hp_sigma_cm']*s); hs=ndi.gaussian_filter(hp,p['smooth_cm']*s)
    o,m,sk=stats(h,s)
    gy,gx=np.gradient(hs); r=p['st_sigma_cm']*s
    Jxx=ndi.gaussian_filter(gx*gx,r); Jyy=ndi.gaussian_filter(gy*gy,r); Jxy=ndi.gaussian_filter(gx*gy,r)
    a=np.mod(-np.degrees(0.5*np.arctan2(2*Jxy,Jxx-Jyy)+0),180.0)  # gradient dir flipped
    a=np.mod(a+90,180.0)
    a=a[sk]; w=1/np.maximum(np.abs(np.cos(np.radians(a))),np.abs(np.sin(np.radians(a))))
    return a,w
def hist_c(a,w,bw):
    n=int(180/bw); k=np.floor(np.mod(a+bw/2,180)/bw).astype(int)%n
    hh=np.bincount(k,weights=w,minlength=n); return hh/hh.sum()
for bw in (10,5):
    for name,h in [('bb',bb),('pine',pn)]:
        L=hist_c(*ang_w(h[:,:512]),bw); R=hist_c(*ang_w(h[:,512:]),bw); T=hist_c(*ang_w(h[:512]),bw); B=hist_c(*ang_w(h[512:]),bw); F=hist_c(*ang_w(h),bw)
        print(bw, name, 'LR', round(emd_circ(L,R,bw),2), 'TB', round(emd_circ(T,B,bw),2), 'L-full', round(emd_circ(L,F,bw),2), 'T-full', round(emd_circ(T,F,bw),2))
    a1,w1=ang_w(bb); a2,w2=ang_w(pn); print(bw,'bb-pine', round(emd_circ(hist_c(a1,w1,bw),hist_c(a2,w2,bw),bw),2))
