; listing: Black Book L63-6 (3x4 matrix transform of a point, optimized)
; source: Abrash, Graphics Programming Black Book, chapter 63, Listing 63.6 (L63-6.ASM)
; cpu: pentium
; published: 34 cycles
; pixels: 1
; branch: none
; run: once
; note: straight-line code, run once. The book annotates one FXCH st(1) as starting on cycle 25
; where the rules pair it with the FADD before it (cycle 24); the total is the same, 34: the
; 33-cycle minimum plus 1.
;
; vec0 = u (3 floats), matrix = 3 rows x 4 floats (m11 m12 m13 m14 / m21.. / m31..), vec1 = v (3 floats)
; v1 = m11u1 + m12u2 + m13u3 + m14, etc.

bits 32

vec0    equ 0x1000
matrix  equ 0x1010
vec1    equ 0x1040

        fld     dword [vec0+0]      ; starts & ends on cycle 0
        fmul    dword [matrix+0]    ; starts on cycle 1
        fld     dword [vec0+0]      ; starts & ends on cycle 2
        fmul    dword [matrix+16]   ; starts on cycle 3
        fld     dword [vec0+0]      ; starts & ends on cycle 4
        fmul    dword [matrix+32]   ; starts on cycle 5
        fld     dword [vec0+4]      ; starts & ends on cycle 6
        fmul    dword [matrix+4]    ; starts on cycle 7
        fld     dword [vec0+4]      ; starts & ends on cycle 8
        fmul    dword [matrix+20]   ; starts on cycle 9
        fld     dword [vec0+4]      ; starts & ends on cycle 10
        fmul    dword [matrix+36]   ; starts on cycle 11
        fxch    st2                 ; no cost
        faddp   st5, st0            ; starts on cycle 12
        faddp   st3, st0            ; starts on cycle 13
        faddp   st1, st0            ; starts on cycle 14
        fld     dword [vec0+8]      ; starts & ends on cycle 15
        fmul    dword [matrix+8]    ; starts on cycle 16
        fld     dword [vec0+8]      ; starts & ends on cycle 17
        fmul    dword [matrix+24]   ; starts on cycle 18
        fld     dword [vec0+8]      ; starts & ends on cycle 19
        fmul    dword [matrix+40]   ; starts on cycle 20
        fxch    st2                 ; no cost
        faddp   st5, st0            ; starts on cycle 21
        faddp   st3, st0            ; starts on cycle 22
        faddp   st1, st0            ; starts on cycle 23
        fxch    st2                 ; no cost
        fadd    dword [matrix+12]   ; starts on cycle 24
        fxch    st1                 ; starts on cycle 25
        fadd    dword [matrix+28]   ; starts on cycle 26
        fxch    st2                 ; no cost
        fadd    dword [matrix+44]   ; starts on cycle 27
        fxch    st1                 ; no cost
        fstp    dword [vec1+0]      ; starts on cycle 28, ends on cycle 29
        fstp    dword [vec1+8]      ; starts on cycle 30, ends on cycle 31
        fstp    dword [vec1+4]      ; starts on cycle 32, ends on cycle 33
