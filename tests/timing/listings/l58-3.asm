; listing: Black Book L58-3
; source: Abrash, Graphics Programming Black Book, ch. 58, Listing 58.3 (L58-3.ASM), one REPT LOOP_UNROLL repetition (SCANOFFSET = 0)
; cpu: 486
; published: 9 cycles per pixel
; pixels: 1
; branch: taken (no Y carry); by the 486 rules a Y carry costs 2 more (docs/cycles.md, "Calibration")
; note: 16-bit segment; ADD EDX,ECX carries a 66h size prefix (author: costs 1 cycle on 486); texel read via [bp] uses SS, no segment prefix; unrolled body, no loop-closing branch; jz is the data-dependent Y-carry test
;
; Vertical column, 16-bit segment: EDX holds both source fractions (Y in the
; low 15 bits with bit 15 as a carry catcher, X in the high word); one ADD
; steps both, ADC adds the summed integer steps plus the X carry, and bit 15
; of DX signals a Y carry that needs one more row of texture.
; Registers: AX texture row step, ECX fraction steps, EDX fractions,
; SI summed integer step, DS:DI destination, SS:BP texel pointer.
; Later repetitions would store to [di+n*SCANWIDTH]; this first one has no
; displacement.

bits 16

        mov     bl,[bp]                         ; fetch texel (SS default)
        mov     [di],bl                         ; store to screen

        add     edx,ecx                         ; step both fractions
        adc     bp,si                           ; integer step + X carry
        test    dh,80h                          ; Y fraction carried?
        jz      NoYCarry
        add     bp,ax                           ; one more texture row
        and     dh,~80h                         ; clear the catcher bit (7Fh)
NoYCarry:
