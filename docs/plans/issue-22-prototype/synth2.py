import sys; sys.path.insert(0,'/tmp/research22')
from proto import *
from scale import down
import numpy as np
rng=np.random.default_rng(5); N=1024; s=10
h=0.15*ndi.gaussian_filter(rng.standard_normal((N,N)),4)*4
y,x=np.mgrid[0:N,0:N].astype(float)
for k in range(260):
    cx=rng.uniform(0,N); cy=rng.uniform(0,N); L=rng.uniform(50,200); W=rng.uniform(3,8); tilt=rng.normal(0,0.08)
    dx=np.abs(x-(cx+tilt*(y-cy))); inside=(np.abs(y-cy)<L/2)
    h-= np.where(inside, np.clip(1-dx/(W/2),0,1),0)
a=stats(h,10)[0]; b=stats(down(h,2),5)[0]; c=stats(down(h,2),10)[0]
print('declared', round(score(a,b)[0],3), 'mismatch', round(score(a,c)[0],3))
print(fmt(a))
