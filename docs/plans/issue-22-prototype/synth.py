import sys; sys.path.insert(0,'/tmp/research22')
from proto import *
s=10.0; N=512
y,x=np.mgrid[0:N,0:N].astype(float)
def stripes(P,W,angle_deg=90,prof='box'):
    # fissures along direction angle (deg from +x, counter-clockwise; image y down)
    a=np.radians(angle_deg)
    # coordinate across the fissures
    u = x*np.sin(a) + y*np.cos(a)   # for angle 90: u = x
    d = np.mod(u, P)
    if prof=='box': return -(d < W).astype(float)
    q=np.abs(d-(W-1)/2)/(W/2); return -np.clip(1-q,0,1)  # V
for P,W in [(32,5),(40,8),(25,3),(60,12)]:
    o=stats(stripes(P,W),s)[0]
    print(f'P={P} W={W}: sp_h={o["spacing_h_mean"]*s:.2f}px std={o["spacing_h_std"]*s:.2f} width={o["width_mean"]*s:.2f}px edtw={o["width_edt_mean"]*s:.2f} ff={o["fissure_fraction"]:.4f} (W/P={W/P:.4f}) vf={o["vertical_fraction"]:.3f} len={o["length_median"]*s:.0f}px dr={o["depth_ratio"]:.2f}')
for ang in [90,60,45,30,0]:
    o=stats(stripes(32,5,ang),s)[0]; h=o['hist']; c=(np.arange(18)+0.5)*10
    print(f'angle {ang}: peak bin centre {c[np.argmax(h)]:.0f}, mass in peak±1 bin {h[max(0,np.argmax(h)-1):np.argmax(h)+2].sum():.3f}, mean angle {np.degrees(0.5*np.angle((h*np.exp(2j*np.radians(c))).sum()))%180:.1f}, vf={o["vertical_fraction"]:.3f}, sp_h={o["spacing_h_mean"]*s:.2f}px width={o["width_mean"]*s:.2f}')
rng=np.random.default_rng(1)
f=stripes(32,5)+0.05*ndi.gaussian_filter(rng.standard_normal((N,N)),3)
a=stats(f,s)[0]; b=stats(3.7*f+12.0,s)[0]
print('affine: max abs diff', max(abs(a[k]-b[k]) for k in CORE), 'score', score(a,b)[0])
noise=ndi.gaussian_filter(rng.standard_normal((N,N)),5)
c=stats(noise,s)[0]
print('stripes vs isotropic noise score', round(score(a,c)[0],3), 'emd', round(emd_circ(a['hist'],c['hist']),1), fmt(c))
