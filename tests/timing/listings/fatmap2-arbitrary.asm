; listing: fatmap2 sec. 14 arbitrary-size loop
; source: Byggmastar, fatmap2.txt (1997), sec. 14, arbitrary-size bitmap inner loop (after Chris Hecker)
; cpu: pentium
; published: 5 cycles per pixel
; pixels: 1
; branch: none
; note: 32-bit flat; loop-closing branch is the final jnz (taken, predicted) on the flags of inc ecx; ECX runs from -width up to 0; duvdxstep and dvdxfrac are memory operands; author's figure assumes perfect pairing and no cache misses
;
; EBP is 0 or -1 from the previous v fraction carry (SBB) and selects one of
; two texture-pointer steps (with or without one extra row); the u fraction
; carry (EAX += EDX) rides in through ADC. The v fraction is the top of EBX;
; BL doubles as the texel register. ESI texel pointer, EDI end of span.

bits 32

duvdxstep equ 0x1000                    ; two dwords: step with / without the extra row
dvdxfrac  equ 0x1008                    ; dword: v fraction step (high 16 bits)

inner:
        add     eax,edx                 ; u fraction
        mov     bl,[esi]                ; fetch texel
        adc     esi,[duvdxstep+4+ebp*4] ; pointer step (+1 on u carry)
        add     ebx,[dvdxfrac]          ; v fraction
        sbb     ebp,ebp                 ; -1 if v carried, else 0
        mov     [edi+ecx],bl            ; store pixel
        inc     ecx
        jnz     inner
