; listing: Black Book L63-3 (dot product, optimized with FXCH)
; source: Abrash, Graphics Programming Black Book, chapter 63, Listing 63.3 (L63-3.ASM)
; cpu: pentium
; published: 15 cycles
; pixels: 1
; branch: none
; run: once
; note: straight-line code, run once. As L63-2 with the FMULs first and an FXCH ("no cost", paired
; in V): the 10-cycle minimum plus 5.
;
; vec0 = u (3 floats), vec1 = v (3 floats), dot = result float

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
        fxch    st1                 ; no cost
        faddp   st2, st0            ; starts on cycle 6
                                    ; stalls for cycles 7-8
        faddp   st1, st0            ; starts on cycle 9
                                    ; stalls for cycles 10-12
        fstp    dword [dot]         ; starts on cycle 13, ends on cycle 14
