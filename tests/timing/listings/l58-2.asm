; listing: Black Book L58-2
; source: Abrash, Graphics Programming Black Book, ch. 58, Listing 58.2 (L58-2.ASM), one REPT LOOP_UNROLL repetition
; cpu: 486
; published: 22 cycles per pixel
; pixels: 1
; branch: any (a JNC taken costs what falling through to its ADD does, and no carry path stalls)
; note: 16-bit real mode; unrolled body, no loop-closing branch (the file falls off its end into the next copy); both jnc are forward, data-dependent
;
; Vertical column, one pixel per pass: the plane is fixed outside the loop,
; so only the texel copy and the 16.16 source step remain; the carry out of
; the Y fraction add is reused by ADC DI,DX to step down one scanline.
; Registers: DS:BX texel pointer, DX scanline pitch (+ or -), ES:DI
; destination, SS:BP local variable frame.

bits 16

; word-sized locals addressed off BP (offsets are arbitrary but distinct)
X_BASE_ADVANCE   equ 0
SOURCE_STEP_X    equ 2
SOURCE_X         equ 4
X_ADVANCE_BY_ONE equ 6
Y_BASE_ADVANCE   equ 8
SOURCE_STEP_Y    equ 10
SOURCE_Y         equ 12
Y_ADVANCE_BY_ONE equ 14

        mov     ah,[bx]                         ; fetch texel
        mov     [es:di],ah                      ; store to screen

        add     bx,[bp+X_BASE_ADVANCE]          ; integer X step
        mov     cx,word [bp+SOURCE_STEP_X]
        add     word [bp+SOURCE_X],cx           ; X fraction
        jnc     NoExtraXAdvance
        add     bx,[bp+X_ADVANCE_BY_ONE]        ; X fraction carried
NoExtraXAdvance:

        add     bx,[bp+Y_BASE_ADVANCE]          ; integer Y step
        mov     cx,word [bp+SOURCE_STEP_Y]
        add     word [bp+SOURCE_Y],cx           ; Y fraction
        jnc     NoExtraYAdvance
        add     bx,[bp+Y_ADVANCE_BY_ONE]        ; Y fraction carried
NoExtraYAdvance:

        adc     di,dx                           ; next scanline down the column
