; listing: Black Book L63-4 (cross product, unoptimized)
; source: Abrash, Graphics Programming Black Book, chapter 63, Listing 63.4 (L63-4.ASM)
; cpu: pentium
; published: 36 cycles
; pixels: 1
; branch: none
; run: once
; note: straight-line code, run once. Each component computed and stored in turn: the 21-cycle
; minimum plus 15 lost to stalls.
;
; vec0 = u (3 floats), vec1 = v (3 floats), vec2 = u x v = [u2v3-u3v2, u3v1-u1v3, u1v2-u2v1]

bits 32

vec0    equ 0x1000
vec1    equ 0x1010
vec2    equ 0x1020

        fld     dword [vec0+4]      ; starts & ends on cycle 0
        fmul    dword [vec1+8]      ; starts on cycle 1
        fld     dword [vec0+8]      ; starts & ends on cycle 2
        fmul    dword [vec1+4]      ; starts on cycle 3
                                    ; stalls for cycles 4-5
        fsubrp  st1, st0            ; starts on cycle 6
                                    ; stalls for cycles 7-9
        fstp    dword [vec2+0]      ; starts on cycle 10, ends on cycle 11
        fld     dword [vec0+8]      ; starts & ends on cycle 12
        fmul    dword [vec1+0]      ; starts on cycle 13
        fld     dword [vec0+0]      ; starts & ends on cycle 14
        fmul    dword [vec1+8]      ; starts on cycle 15
                                    ; stalls for cycles 16-17
        fsubrp  st1, st0            ; starts on cycle 18
                                    ; stalls for cycles 19-21
        fstp    dword [vec2+4]      ; starts on cycle 22, ends on cycle 23

        fld     dword [vec0+0]      ; starts & ends on cycle 24
        fmul    dword [vec1+4]      ; starts on cycle 25
        fld     dword [vec0+4]      ; starts & ends on cycle 26
        fmul    dword [vec1+0]      ; starts on cycle 27
                                    ; stalls for cycles 28-29
        fsubrp  st1, st0            ; starts on cycle 30
                                    ; stalls for cycles 31-33
        fstp    dword [vec2+8]      ; starts on cycle 34, ends on cycle 35
