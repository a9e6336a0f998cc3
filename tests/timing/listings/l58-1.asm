; listing: Black Book L58-1
; source: Abrash, Graphics Programming Black Book, ch. 58, Listing 58.1 (L58-1.ASM)
; cpu: 486
; published: 44 cycles per pixel
; pixels: 1
; branch: 0.5 (the author: "2 taken jumps (plus 1 not taken)" a pixel, the JNZ among them: one JNC of two taken); a JNC taken costs what falling through to its ADD does
; note: 16-bit real mode; loop-closing branch is the final jnz (taken); author counts OUT as 16 cycles (real mode) and ROL as 2; fields on SS:BP are word locals
;
; Mode X horizontal scanline, one pixel per pass: select the plane with OUT,
; copy one texel, step the 16.16 source coordinates (fraction carries via
; two jnc), then rotate the plane mask and bump DI when it wraps to plane 0.
; Registers: AL plane mask, DS:BX texel pointer, DX sequencer data port,
; SI pixel count, ES:DI destination, SS:BP local variable frame.

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

TexScanLoop:
        out     dx,al                           ; plane select for this pixel
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

        rol     al,1                            ; next plane
        adc     di,0                            ; next address after plane 3

        dec     si
        jnz     TexScanLoop
