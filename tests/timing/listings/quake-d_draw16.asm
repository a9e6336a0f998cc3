; listing: Quake's D_DrawSpans16, one 16-pixel segment of its loop
; source: id Software, WinQuake d_draw16.s (1999 GPL release), LNotLastSegment to its jump back,
;   rotated to start at LSetupNotLast2 (the next segment's FDIV set up)
; cpu: pentium
; published: 7.5 cycles per pixel
; pixels: 16
; precision: 24
; branch: taken: t's step has no whole texel (LZero, no IMUL); not-taken: the IMUL path
; note: the Black Book's chapter 68 gives 7.5 cycles a pixel for the routine, its FDIV overlapped
;   with the pixels (chapter 70: "the FDIV effectively takes only one cycle"); a figure for the
;   routine, not a count of this sequence. Quake runs it at single precision with chop (sys_dosa.s),
;   so its FDIV takes 19 cycles.
; note: left out: the clamps' branches (their compares kept; in range they are not taken), the last-
;   segment and short-span paths; the loop's own jump back (the body falls into the next copy). The
;   LZero branch is kept: the only data-dependent branch.
;
; esi texel pointer, edi destination, ebx s fraction, edx t fraction, ebp s step (fraction, shifted
; left 12), ecx the carry's advance-table index, al the texel. The x87 stack at the top: 1/z, t/z, s/z.

bits 32

zi16stepu       equ 0x2000
sdivz16stepu    equ 0x2004
tdivz16stepu    equ 0x2008
fp_64k          equ 0x200c
counttemp       equ 0x2010
tstep           equ 0x2014
advancetable    equ 0x2018
tfracf          equ 0x2020
sfracf          equ 0x2024
snext           equ 0x2028
tnext           equ 0x202c
s               equ 0x2030
t               equ 0x2034
sadjust         equ 0x2038
tadjust         equ 0x203c
bbextents       equ 0x2040
bbextentt       equ 0x2044
cachewidth      equ 0x2048

; LSetupNotLast2
        fadd    dword [zi16stepu]
        fxch    st2
        fadd    dword [sdivz16stepu]
        fxch    st2
        fld     dword [tdivz16stepu]
        faddp   st2, st0
        fld     dword [fp_64k]
        fdiv    st0, st1
; LFDIVInFlight2
        mov     [counttemp], ecx

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+8], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+9], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+10], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+11], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+12], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+13], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+14], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edi, 16
        mov     [tfracf], edx
        mov     edx, [snext]
        mov     [sfracf], ebx
        mov     ebx, [tnext]
        mov     [s], edx
        mov     [t], ebx

        mov     ecx, [counttemp]
        cmp     ecx, 16
        mov     [edi-1], al
; LNotLastSegment
        fld     st0
        fmul    st0, st4
        fxch    st1
        fmul    st0, st3
        fxch    st1
        fistp   dword [snext]
        fistp   dword [tnext]
        mov     eax, [snext]
        mov     edx, [tnext]

        mov     bl, [esi]
        sub     ecx, 16
        mov     ebp, [sadjust]
        mov     [counttemp], ecx

        mov     ecx, [tadjust]
        mov     [edi], bl

        add     ebp, eax
        add     ecx, edx

        mov     eax, [bbextents]
        mov     edx, [bbextentt]

        cmp     ebp, 4096
        cmp     ebp, eax
        cmp     ecx, 4096
        cmp     ecx, edx

        mov     [snext], ebp
        mov     [tnext], ecx

        sub     ebp, [s]
        sub     ecx, [t]

        mov     eax, ecx
        mov     edx, ebp
        sar     eax, 20
        jz      .zero
        sar     edx, 20
        mov     ebx, [cachewidth]
        imul    eax, ebx
        jmp     .setup1
.zero:
        sar     edx, 20
        mov     ebx, [cachewidth]
.setup1:
        add     eax, edx
        mov     edx, [tfracf]
        mov     [advancetable+4], eax
        add     eax, ebx
        shl     ebp, 12
        mov     ebx, [sfracf]
        shl     ecx, 12
        mov     [advancetable], eax

        mov     [tstep], ecx
        add     edx, ecx

        sbb     ecx, ecx
        add     ebx, ebp
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     al, [esi]
        add     ebx, ebp
        mov     [edi+1], al
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+2], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+3], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+4], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+5], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+6], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        add     edx, [tstep]
        sbb     ecx, ecx
        mov     [edi+7], al
        add     ebx, ebp
        mov     al, [esi]
        adc     esi, [advancetable+4+ecx*4]

        mov     ecx, [counttemp]
        cmp     ecx, 16
