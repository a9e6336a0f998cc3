; listing: Black Book L63-2 (dot product, unoptimized)
; source: Abrash, Graphics Programming Black Book, chapter 63, Listing 63.2 (L63-2.ASM)
; cpu: pentium
; published: 17 cycles
; pixels: 1
; branch: none
; run: once
; note: straight-line code, run once. The book numbers cycles from 0 and counts to the end of the
; last FSTP (2 cycles): its 17 is cycles 0 to 16, the 10-cycle minimum plus 7 lost to stalls. Data
; in the cache; 32-bit floats.
;
; vec0 = u (3 floats), vec1 = v (3 floats), dot = result float; d = u1v1 + u2v2 + u3v3

bits 32

vec0    equ 0x1000
vec1    equ 0x1010
dot     equ 0x1020

        fld     dword [vec0+0]      ; starts & ends on cycle 0
        fmul    dword [vec1+0]      ; starts on cycle 1
        fld     dword [vec0+4]      ; starts & ends on cycle 2
        fmul    dword [vec1+4]      ; starts on cycle 3
        fld     dword [vec0+8]      ; starts & ends on cycle 4
        fmul    dword [vec1+8]      ; starts on cycle 5
                                    ; stalls for cycles 6-7
        faddp   st1, st0            ; starts on cycle 8
                                    ; stalls for cycles 9-10
        faddp   st1, st0            ; starts on cycle 11
                                    ; stalls for cycles 12-14
        fstp    dword [dot]         ; starts on cycle 15, ends on cycle 16
