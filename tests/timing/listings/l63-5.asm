; listing: Black Book L63-5 (cross product, optimized/interleaved)
; source: Abrash, Graphics Programming Black Book, chapter 63, Listing 63.5 (L63-5.ASM)
; cpu: pentium
; published: 22 cycles
; pixels: 1
; branch: none
; run: once
; note: straight-line code, run once. All six FMULs first, FXCH to bring each result up: the
; 21-cycle minimum plus 1.
;
; vec0 = u (3 floats), vec1 = v (3 floats), vec2 = u x v

bits 32

vec0    equ 0x1000
vec1    equ 0x1010
vec2    equ 0x1020

        fld     dword [vec0+4]      ; starts & ends on cycle 0
        fmul    dword [vec1+8]      ; starts on cycle 1
        fld     dword [vec0+8]      ; starts & ends on cycle 2
        fmul    dword [vec1+0]      ; starts on cycle 3
        fld     dword [vec0+0]      ; starts & ends on cycle 4
        fmul    dword [vec1+4]      ; starts on cycle 5
        fld     dword [vec0+8]      ; starts & ends on cycle 6
        fmul    dword [vec1+4]      ; starts on cycle 7
        fld     dword [vec0+0]      ; starts & ends on cycle 8
        fmul    dword [vec1+8]      ; starts on cycle 9
        fld     dword [vec0+4]      ; starts & ends on cycle 10
        fmul    dword [vec1+0]      ; starts on cycle 11
        fxch    st2                 ; no cost
        fsubrp  st5, st0            ; starts on cycle 12
        fsubrp  st3, st0            ; starts on cycle 13
        fsubrp  st1, st0            ; starts on cycle 14
        fxch    st2                 ; no cost
                                    ; stalls for cycle 15
        fstp    dword [vec2+0]      ; starts on cycle 16, ends on cycle 17
        fstp    dword [vec2+4]      ; starts on cycle 18, ends on cycle 19
        fstp    dword [vec2+8]      ; starts on cycle 20, ends on cycle 21
