; listing: Black Book L58-4
; source: Abrash, Graphics Programming Black Book, ch. 58, Listing 58.4 (L58-4.ASM), one REPT LOOP_UNROLL repetition (SCANOFFSET = 0)
; cpu: 486
; published: 8 cycles per pixel
; published-pentium: 5.5
; pixels: 1
; branch: any on the 486 (a JZ taken costs what falling through to ADD and AND does)
; branch-pentium: average - author: the Y-carry path (jz not taken, ADD ESI,ECX then a 1-cycle AGI on the next MOV BL,[ESI]) "happens about half the time"
; note: 32-bit segment, no prefixes; unrolled body, no loop-closing branch; the AGI the Pentium figure counts falls on the first instruction of the next pass
;
; Same scheme as L58-3 in a 32-bit segment: the store is moved after the
; ADC so the byte load has time to land (486), and the size prefix is gone.
; Registers: EAX summed integer step, ECX texture row step, EDX fractions,
; ESI texel pointer, EDI destination, EBP fraction steps.
; Later repetitions would store to [edi+n*SCANWIDTH]; this first one has no
; displacement.

bits 32

        mov     bl,[esi]                        ; fetch texel
        add     edx,ebp                         ; step both fractions
        adc     esi,eax                         ; integer step + X carry
        mov     [edi],bl                        ; store to screen
        test    dh,80h                          ; Y fraction carried?
        jz      short NoYCarry
        add     esi,ecx                         ; one more texture row
        and     dh,~80h                         ; clear the catcher bit (7Fh)
NoYCarry:
