#!/usr/bin/env python3
"""Lists the non-test functions over N lines (env N, default 100; `fn` line to closing brace, by
brace count; test modules and tests.rs / *_tests.rs skipped) under the given roots (default:
src, surrogate/src, dem/src). Usage: python3 scripts/long-functions.py [--check] [ROOT...]
With --check it exits 1 when a function is over the limit (the limit itself is enforced by
tests/architecture, `no_function_over_100_lines`)."""
import re,sys,os
N=int(os.environ.get('N','100'))
args=sys.argv[1:]
check='--check' in args
roots=[a for a in args if a!='--check'] or ['src','surrogate/src','dem/src']
def strip(line, state):
    # remove strings, chars and comments; state: in block comment / raw string
    out='';i=0
    while i<len(line):
        if state['blk']:
            j=line.find('*/',i)
            if j<0: return out,state
            state['blk']=False; i=j+2; continue
        if state['str']:
            j=i
            while j<len(line):
                if line[j]=='\\': j+=2; continue
                if line[j]=='"': break
                j+=1
            if j>=len(line): return out,state
            state['str']=False; i=j+1; continue
        c=line[i]
        if line.startswith('//',i): return out,state
        if line.startswith('/*',i): state['blk']=True; i+=2; continue
        m=re.match(r'r(#*)"',line[i:])
        if m and (i==0 or not (line[i-1].isalnum() or line[i-1]=='_')):
            end='"'+m.group(1); j=line.find(end,i+len(m.group(0)))
            if j<0: state['str']=False; return out,state  # multi-line raw: approx
            i=j+len(end); continue
        if c=='"': state['str']=True; i+=1; continue
        if c=="'":
            m=re.match(r"'(\\.|[^\\'])'",line[i:])
            if m: i+=len(m.group(0)); continue
        out+=c; i+=1
    return out,state
res=[]
for root in roots:
    for dp,_,fs in os.walk(root):
        for f in fs:
            if not f.endswith('.rs') or f=='tests.rs' or f.endswith('_tests.rs'): continue
            p=os.path.join(dp,f); L=open(p).read().split('\n')
            st={'blk':False,'str':False}; clean=[]
            for l in L:
                c,st=strip(l,st); clean.append(c)
            i=0; skip_until=-1
            while i<len(clean):
                l=clean[i]
                if re.match(r'\s*#\[cfg\(test\)\]',L[i]):
                    # skip the next item
                    j=i+1; d=0; started=False
                    while j<len(clean):
                        d+=clean[j].count('{')-clean[j].count('}')
                        if '{' in clean[j]: started=True
                        if started and d<=0: break
                        if not started and clean[j].rstrip().endswith(';'): break
                        j+=1
                    i=j+1; continue
                m=re.search(r'\bfn\s+([A-Za-z_0-9]+)',l)
                if m:
                    j=i; d=0; started=False
                    while j<len(clean):
                        for ch in clean[j]:
                            if ch=='{': d+=1; started=True
                            elif ch=='}': d-=1
                        if started and d==0: break
                        if not started and clean[j].rstrip().endswith(';'): break
                        j+=1
                    if started:
                        n=j-i+1
                        if n>N: res.append((n,p,i+1,m.group(1)))
                    i+=1; continue
                i+=1
for r in sorted(res,reverse=True): print(f'{r[0]:5d} {r[1]}:{r[2]} {r[3]}')
print('total',len(res))
if check:
    sys.exit(1 if res else 0)
